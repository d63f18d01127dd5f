#!/bin/sh
# On exit 2 with --json, the bad_input document's "message" is the whole
# first line of what stderr says (less its "acbb: "), for every kind of
# message that used to be finished with writes beside the one reporter
# (cli/say.h): the preset search list, "did you mean", a message longer
# than the reporter's buffer. And nothing in cli/ writes to stderr but the
# reporter (say.c) and the progress line (progress.c), so no message can
# bypass it again. TAP. $1 = the acbb binary; cwd = repository root.
set -u
ACBB=${1:?usage: test_json_message.sh path/to/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-jmsg.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

P=presets/7008C.ini
# A user directory whose name makes the preset search message ~2300
# bytes, beyond the reporter's 2 kB buffer (it need not exist).
LONGDIR=$TMP/$(printf 'd%.0s' $(seq 2200))

# same NAME TAIL ARGS...: exit 2, one bad_input document whose message is
# stderr's first line without "acbb: ", and that line ends with TAIL.
same() {
    name=$1 tail=$2
    shift 2
    XDG_CONFIG_HOME=${XDG:-$TMP/xdg} "$ACBB" "$@" --json >"$TMP/out" 2>"$TMP/err"
    code $? 2 "$name"
    line=$(head -n 1 "$TMP/err")
    msg=$(jq -r 'select(.status == "bad_input") | .message' "$TMP/out" 2>/dev/null)
    [ "$(wc -l <"$TMP/out")" -eq 1 ] && [ "acbb: $msg" = "$line" ]
    t $? "$name: the document's message is stderr's line (${#msg} bytes)"
    case $line in *"$tail") true ;; *) false ;; esac
    t $? "$name: ... which ends '$tail'"
}

same "run of an unknown preset" '(see `acbb presets`)' run nothere
same "sweep of an unknown preset" '(see `acbb presets`)' sweep nothere
XDG=$LONGDIR same "an unknown preset, a 2 kB search list" '(see `acbb presets`)' run nothere
same "an unknown option near one" '; did you mean --json?' run "$P" --jso
same "an unknown command near one" "; did you mean 'run'?" rn
same "a missing preset" 'run: missing PRESET' run
same "a command without its subcommand" 'bench: expected one of:' bench
# The hint lines after the first still reach stderr, in the same message.
sed -n 2p "$TMP/err" | grep -q '^  acbb bench speed'
t $? "bench: ... followed by the subcommands' synopses"

# Only the reporter and the progress line write to stderr: any other
# write in cli/ (comments and string literals aside) is a message that
# bypasses the JSON document. Passing stderr to the progress line is fine.
for f in cli/*.c; do
    case $f in cli/say.c|cli/progress.c) continue ;; esac
    sed -e 's,/\*.*\*/,,g' -e 's,^ *\*.*,,' -e 's,^ */\*.*,,' -e 's/"\([^"\\]\|\\.\)*"/""/g' "$f" |
        grep -nE '\bstderr\b|\bperror\b|STDERR_FILENO|\bdprintf\b|\berr\(|\bwarnx?\(' |
        grep -vE 'acbb_cli_progress_(init|wanted)\([^;]*\bstderr\b' | sed "s|^|$f:|"
done >"$TMP/bypass"
[ ! -s "$TMP/bypass" ]
t $? "nothing in cli/ writes to stderr but say.c and progress.c"
sed 's/^/# bypasses the reporter: /' "$TMP/bypass"

tap_done
