# Shared TAP helpers for the shell tests (sourced, not run). The sourcing
# script sets TMP (its scratch directory; "$TMP/err" holds the last stderr)
# and ends with `tap_done`.
n=0
failed=0

# t STATUS NAME: one TAP result from a command's exit status.
t() {
    n=$((n + 1))
    if [ "$1" -eq 0 ]; then
        echo "ok $n - $2"
    else
        echo "not ok $n - $2"
        failed=$((failed + 1))
    fi
}

# skip NAME REASON: a check that cannot run here, reported as
# "ok N - NAME # SKIP REASON" (counted, never a failure).
skip() {
    n=$((n + 1))
    echo "ok $n - $1 # SKIP $2"
}

# jqt FILE FILTER NAME: the jq filter must evaluate to true on FILE.
jqt() {
    jq -e "def abs: if . < 0 then -. else . end; $2" "$1" >/dev/null 2>&1
    t $? "$3"
}

# has FILE TEXT NAME: FILE contains TEXT literally.
has() {
    grep -F -q -- "$2" "$1"
    t $? "$3"
}

# code GOT WANT NAME: an exit status; on a mismatch the captured stderr is shown.
code() {
    [ "$1" -eq "$2" ]
    t $? "$3 (exit $1, want $2)"
    [ "$1" -eq "$2" ] || sed 's/^/# /' "$TMP/err" 2>/dev/null | head -5
}

# tap_done: the plan, and the script's exit status.
tap_done() {
    echo "1..$n"
    [ "$failed" -eq 0 ]
}
