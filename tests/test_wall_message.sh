#!/bin/sh
# fidelity.max_wall_s (--max-wall) met in the set-up and met while stepping
# print one form on stderr, as every named ending does ("not_converged: ..."):
#   acbb: wall_limit: wall-clock bound fidelity.max_wall_s = S s reached<how>
# where <how> is "; last good state kept" (a step) or " during the set-up,
# before the first state" (no state yet). Before, the set-up's line lacked
# the status name ("acbb: wall-clock bound ..."). The JSON's message is the
# same text after "wall_limit: ". TAP.
# Which path a run takes is forced, not timed: a dynamic-level set-up
# (every ball's first window, 21 balls) takes far longer than 1 ms on any
# machine; a quasi-static set-up takes milliseconds, and a [schedule] of
# 9e7 s (minutes of steps) is still stepping at 0.5 s (the run's JSON says
# which path: iterations 0 or >= 1). Set-up: one bearing, a set, a spindle;
# a step: one bearing (every plant's step failure is stepper.c's one text).
# Usage: test_wall_message.sh PATH/TO/acbb   (cwd = repo root)
set -u
ACBB=${1:?usage: test_wall_message.sh PATH/TO/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-wallmsg.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
SETUP_TAIL=" during the set-up, before the first state"
STEP_TAIL="; last good state kept"

# wall NAME WANT_ITER LINE -- ARGS: one run; its stderr holds LINE exactly,
# once, and no other wall-clock line; its JSON agrees; the path is the one
# meant (iterations 0: set-up, >= 1: a step).
wall() {
    name=$1 iter=$2 line=$3
    shift 4
    "$ACBB" run "$@" --json >"$TMP/out.json" 2>"$TMP/err"
    code $? 3 "$name: exit 3"
    [ "$(grep -c -F 'wall' "$TMP/err")" -eq 1 ] && grep -q -x -F -- "$line" "$TMP/err"
    t $? "$name: stderr says exactly '$line'$(grep -F wall "$TMP/err" | grep -v -x -F -- "$line" |
          head -2 | sed 's/^/ (got: /; s/$/)/' | tr '\n' ' ')"
    jq -e --arg m "${line#acbb: wall_limit: }" --argjson i "$iter" '.status == "wall_limit"
        and .message == $m and (if $i == 0 then .iterations == 0 else .iterations >= 1 end)' \
        "$TMP/out.json" >/dev/null 2>&1
    t $? "$name: the JSON says wall_limit, the same message, $( [ "$iter" -eq 0 ] &&
          echo 'no step' || echo 'some steps')"
    sed -E 's/ = [0-9.e+-]+ s reached.*//' "$TMP/err" | grep -F wall >>"$TMP/heads"
}

CL="presets/combined-load.ini --set fidelity.model=dynamic"
# shellcheck disable=SC2086
wall "set-up, one bearing" 0 \
    "acbb: wall_limit: wall-clock bound fidelity.max_wall_s = 0.001 s reached$SETUP_TAIL" \
    -- $CL --max-wall 0.001
wall "set-up, a bearing set" 0 \
    "acbb: wall_limit: wall-clock bound fidelity.max_wall_s = 0.001 s reached$SETUP_TAIL" \
    -- presets/pair-DB-heated.ini --set fidelity.model=dynamic --max-wall 0.001
# A spindle's set-up (two sets' first equilibria, over 50 ms) said "spindle
# front set: ... reached; last good state kept" with no state to keep.
wall "set-up, a spindle" 0 \
    "acbb: wall_limit: wall-clock bound fidelity.max_wall_s = 0.001 s reached$SETUP_TAIL" \
    -- presets/spindle-belt-DB.ini --max-wall 0.001

cp presets/7008C.ini "$TMP/long.ini"
sed -i 's/^max_time_s = .*/max_time_s = 1e8/; s/^max_steps = .*/max_steps = 10000000/' \
    "$TMP/long.ini"
printf '\n[schedule]\nrow = 0, 15000, 300, 0\nrow = 90000000, 15000, 300, 0\n' >>"$TMP/long.ini"
wall "a step, one bearing" 1 \
    "acbb: wall_limit: wall-clock bound fidelity.max_wall_s = 0.5 s reached$STEP_TAIL" \
    -- "$TMP/long.ini" --set fidelity.model=quasi-static --max-wall 0.5

# The run summary's status line carries the whole message, wrapped under
# itself within 80 columns (it was cut at 60 characters: "...; last g").
"$ACBB" run "$TMP/long.ini" --set fidelity.model=quasi-static --max-wall 0.5 \
    >"$TMP/sum" 2>/dev/null
sed -n '/^status /{N;p}' "$TMP/sum" | tr -s ' \n' ' ' >"$TMP/st"
grep -q -x -F "status wall_limit: wall-clock bound fidelity.max_wall_s = 0.5 s reached; last good state kept " \
    "$TMP/st" && [ "$(awk 'length > 80' "$TMP/sum" | wc -l)" -eq 0 ]
t $? "the run summary's status: the whole message within 80 columns (got: $(cat "$TMP/st"))"
# The transient took the whole bound, so the steady branch has no state:
# nothing to compare (its zeros used to read as differences, "DIFFERENT").
grep -q -x 'branches     not compared: the steady solve reached no state' "$TMP/sum" &&
    grep -E -q '^steady    wall_limit( +-){6}$' "$TMP/sum"
t $? "the branches block: not compared, the steady row without numbers"

# A sensitivity's base run that met the bound says so in the same form
# (it said "the base run: wall-clock bound ..." without the status name).
# shellcheck disable=SC2086
"$ACBB" sensitivity $CL --metric losses_W.total --max-wall 0.001 >/dev/null 2>"$TMP/err"
grep -q -F "; the base run: wall_limit: wall-clock bound fidelity.max_wall_s = 0.001 s reached$SETUP_TAIL" \
    "$TMP/err"
t $? "sensitivity: the base run's failure names its status ($(tail -c 160 "$TMP/err"))"
# ... and with every run failed no input shows an effect (it showed 0, as
# if the input did nothing): '-' in the table, null in the JSON
# shellcheck disable=SC2086
"$ACBB" sensitivity $CL --metric losses_W.total --max-wall 0.001 >"$TMP/sens.txt" 2>/dev/null
# shellcheck disable=SC2086
"$ACBB" sensitivity $CL --metric losses_W.total --max-wall 0.001 --json >"$TMP/sens.json" 2>/dev/null
grep -E -q '^lubricant\.boundary_friction +failed +failed +-$' "$TMP/sens.txt" &&
    jq -e '(.inputs | length) > 10 and all(.inputs[]; .effect == null)' "$TMP/sens.json" >/dev/null
t $? "sensitivity: all runs failed, no effect shown ('-', null)"

# One form: the status name, then the bound and its key, the same words.
[ "$(wc -l <"$TMP/heads")" -eq 4 ] && [ "$(sort -u "$TMP/heads" | wc -l)" -eq 1 ] &&
    grep -q -x -F 'acbb: wall_limit: wall-clock bound fidelity.max_wall_s' "$TMP/heads"
t $? "set-up and step: one form, 'acbb: wall_limit: wall-clock bound fidelity.max_wall_s = S s reached...' ($(sort -u "$TMP/heads" | tr '\n' '|'))"

tap_done
