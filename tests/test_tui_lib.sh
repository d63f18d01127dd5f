# Shared by the tmux TUI tests (test_tui.sh, test_tui2.sh): sourced, not
# run. The TUI runs in a detached tmux session of fixed size on a private
# socket; we type with send-keys, read with capture-pane -p, and poll for
# the expected text instead of sleeping. The tmux server is killed in a trap.
# Needs $1 = PATH/TO/acbb in the caller's arguments.
ACBB=${1:?usage: $0 PATH/TO/acbb}
case $ACBB in /*) ;; *) ACBB=$(pwd)/$ACBB ;; esac
ROOT=$(pwd)

if ! command -v tmux >/dev/null 2>&1; then
    echo "1..0 # SKIP tmux is not installed"
    exit 0
fi

TMP=$(mktemp -d)
SOCK=acbbtest$$
T="tmux -L $SOCK -f /dev/null"
cleanup() {
    $T kill-server >/dev/null 2>&1
    rm -f "${TMUX_TMPDIR:-/tmp}/tmux-$(id -u)/$SOCK" # the server leaves its socket file
    rm -rf "$TMP"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

n=0
failed=0
ok() { # status description
    n=$((n + 1))
    if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; failed=$((failed + 1)); fi
}
S=none # current session; each TUI run gets its own (killing the last
        # session would stop the server while the next one starts)
screen() { $T capture-pane -p -t "$S" 2>/dev/null; }
show() { screen | sed 's/^/#   /'; }
# Every wait below polls for a state (a text on the pane, a file, a
# condition) every 0.05 s. The bound only turns a hang into a failure: at
# least WAIT_FLOOR_S = 30 s whatever a caller asks, so a loaded machine
# that draws late is never judged on time (issue 16 item 6).
WAIT_FLOOR_S=30
wait_ticks() { s=${1:-$WAIT_FLOOR_S}; [ "$s" -lt $WAIT_FLOOR_S ] && s=$WAIT_FLOOR_S; echo $((s * 20)); }
# Poll the pane for a fixed string, up to $2 seconds (at least the floor).
wait_for() {
    i=0
    lim=$(wait_ticks "${2:-}")
    while [ $i -lt $lim ]; do
        if screen | grep -qF -- "$1"; then return 0; fi
        sleep 0.05
        i=$((i + 1))
    done
    echo "# timed out waiting for: $1"
    show
    return 1
}
# Poll for a file to appear.
wait_file() {
    i=0
    lim=$(wait_ticks "${2:-}")
    while [ $i -lt $lim ]; do
        [ -s "$1" ] && return 0
        sleep 0.05
        i=$((i + 1))
    done
    echo "# timed out waiting for the file $1"
    return 1
}
# Poll until the command "$@" succeeds (up to the floor); on a time-out
# say what was awaited and show the pane.
wait_until() {
    i=0
    lim=$(wait_ticks)
    while [ $i -lt $lim ]; do
        "$@" && return 0
        sleep 0.05
        i=$((i + 1))
    done
    echo "# timed out waiting until: $*"
    show
    return 1
}
keys() { $T send-keys -t "$S" "$@"; }
# The TUI has read every key typed so far: its terminal's input queue is
# empty (FIONREAD). For a check that typed keys did nothing. Without
# python3 it cannot be read, and a pause stands in for it.
input_drained() {
    tty=$($T display-message -p -t "$S" '#{pane_tty}')
    if ! command -v python3 >/dev/null 2>&1; then sleep 0.3; return 0; fi
    [ "$(python3 -c 'import fcntl, struct, sys, termios
with open(sys.argv[1], "rb", buffering=0) as f:
    print(struct.unpack("i", fcntl.ioctl(f, termios.FIONREAD, bytes(4)))[0])' "$tty")" = 0 ]
}
# The value after a label on the overview screen.
t5() { screen | sed -n 's/^Outer ring (5) *\([-0-9.]*\).*/\1/p'; }
ptot() { screen | sed -n 's/.*Total *\([-0-9.]*\) .*/\1/p'; }
# The iteration on the status line ("it N t ..."), 0 if not shown.
iter() { v=$(screen | sed -n 's/.* it \([0-9]*\) t .*/\1/p' | head -1); echo "${v:-0}"; }
# Start the TUI in a fresh session: $1 = environment prefix, $2 = exit file,
# $3 = preset in $TMP (default copy.ini).
start() {
    S=$2
    $T new-session -d -s "$S" -x 80 -y 24 \
        "cd '$TMP' && $1 '$ACBB' tui ${TUI_ARGS:-} ${3:-copy.ini}; rc=\$?; stty -a > '$TMP/stty.$2'; echo EXIT=\$rc > '$TMP/$2'; echo EXIT=\$rc; sleep 60"
}
# The index of a preset key in the editor (schema order, as `acbb keys` lists it).
field_index() {
    "$ACBB" keys | grep '^[a-z_]*\.[A-Za-z0-9_]* =' | grep -n "^$1 =" | cut -d: -f1 | awk '{print $1 - 1}'
}
# Home, then j as many times as the index: one send-keys for them all
# (one tmux client per key took seconds for a key a hundred rows down).
goto_field() {
    idx=$(field_index "$1")
    if [ "$idx" -gt 0 ]; then keys Home $(yes j | head -n "$idx"); else keys Home; fi
}
tty_restored() { grep -qw icanon "$1" && grep -qw echo "$1"; }

