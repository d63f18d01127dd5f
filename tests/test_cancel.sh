#!/usr/bin/env bash
# Long runs can be watched and stopped (issue "Nothing lost, nothing
# overwritten, nothing hangs"): SIGINT/SIGTERM end `acbb run` as
# `cancelled`, exit 3, with the last good state in the JSON; a second
# SIGINT kills at once; the progress line (ACBB_PROGRESS=1) is drawn on
# stderr and erased. $1 = the acbb binary.
. "$(dirname "$0")/tap.sh"
ACBB=$1
PRESETS=$PWD/presets
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# caught PID: PID runs acbb (exec done: before it, the forked shell of a
# background job ignores SIGINT) and catches SIGINT and SIGTERM (SigCgt bits
# 2 and 15): the state the signals below wait for, instead of a time (60 s
# only turns a hang into a failure).
caught() {
    local i m exe
    exe=$(readlink -f "$ACBB")
    for ((i = 0; i < 600; i++)); do
        m=$(awk '/^SigCgt:/ { print $2 }' "/proc/$1/status" 2>/dev/null)
        [ "$(readlink "/proc/$1/exe" 2>/dev/null)" = "$exe" ] && [ -n "$m" ] &&
            (( (16#$m & 0x4002) == 0x4002 )) && return 0
        kill -0 "$1" 2>/dev/null || return 1
        sleep 0.1
    done
    return 1
}

# finite FILE NAME: valid JSON (a NaN would not parse) whose every number is finite.
finite() {
    jq -e '[.. | numbers | select(isinfinite or isnan)] | length == 0' "$1" >/dev/null 2>&1
    t $? "$2"
}

# wait_for FILE PATTERN SECONDS: until the (\r-split) FILE shows a line matching PATTERN.
wait_for() {
    local i
    for ((i = 0; i < $3 * 10; i++)); do
        tr '\r' '\n' <"$1" 2>/dev/null | grep -q -- "$2" && return 0
        sleep 0.1
    done
    return 1
}

# 1. The issue's case: the dynamic level of combined-load (set-up alone takes
#    many seconds), SIGINT during the set-up. (How soon it ends is a
#    benchmark, not a test: no clock here.)
#    If the handler was never seen (the process ended first, or the poll
#    could not read it) nothing was asked of the program: the checks are
#    skipped and say so, never passed. A handler seen and then ignored
#    fails them.
"$ACBB" run "$PRESETS/combined-load.ini" --set fidelity.model=dynamic --json \
    >"$TMP/a.json" 2>"$TMP/err" &
pid=$!
if caught $pid; then
    kill -INT $pid
    wait $pid
    rc=$?
    code $rc 3 "dynamic combined-load, SIGINT in the set-up: exit 3"
    jqt "$TMP/a.json" '.status == "cancelled"' "JSON status is cancelled"
    finite "$TMP/a.json" "every number in that JSON is finite"
    has "$TMP/err" "cancelled" "stderr says cancelled"
else
    wait $pid
    echo "# the run ended (exit $?) before its SIGINT handler was seen"
    for what in "SIGINT in the set-up: exit 3" "JSON status cancelled" "finite JSON" \
        "stderr says cancelled"; do
        skip "$what" "the handler was never seen in /proc (nothing was sent)"
    done
fi

# 2. Cancelled after some steps: the last good state is in the output. The
#    dynamic level on combined-load takes its first steps within a second
#    and runs for a few (7008C alone now finishes in a fraction of one).
ACBB_PROGRESS=1 "$ACBB" run "$PRESETS/combined-load.ini" --set fidelity.model=dynamic \
    --json >"$TMP/b.json" 2>"$TMP/b.err" &
pid=$!
if wait_for "$TMP/b.err" '^step [1-9]' 60; then
    kill -TERM $pid
    wait $pid
    rc=$?
    cp "$TMP/b.err" "$TMP/err"
    code $rc 3 "SIGTERM after the first steps: exit 3"
    jqt "$TMP/b.json" '.status == "cancelled" and .iterations >= 1 and .time_s > 0' \
        "JSON: cancelled, with the steps taken and the simulated time"
    jqt "$TMP/b.json" '.temperature_C.outer_ring > 20 and .losses_W.total > 0' \
        "JSON: the last state has heated the outer ring and has losses"
    finite "$TMP/b.json" "every number in that JSON is finite"
    tr '\r' '\n' <"$TMP/b.err" | grep -q '^step [0-9]*  residual [0-9.e+-]* / 1.0e-04 K/s  t [0-9]* s  ETA'
    t $? "the progress line shows step, residual vs target, simulated time and ETA"
    # The line is erased (blanks, then \r) before the final message.
    tr '\r' '\n' <"$TMP/b.err" | grep -B1 '^acbb: cancelled' | head -n 1 | grep -q '^ *$'
    t $? "the progress line is erased before the final message"
else
    kill -KILL $pid 2>/dev/null
    t 1 "the dynamic run took a step within 60 s"
fi

# 3. A second signal kills at once (the first restores the default
#    actions of both). The two are sent back to back; when the first
#    already ended the command before the second arrived, the check cannot
#    tell and is skipped.
second() {   # SIG1 SIG2 WANT CMD...
    local s1=$1 s2=$2 want=$3
    shift 3
    "$ACBB" "$@" >/dev/null 2>"$TMP/err" &
    pid=$!
    caught $pid
    kill -"$s1" $pid
    kill -"$s2" $pid 2>/dev/null
    wait $pid
    rc=$?
    if [ $rc -eq 3 ]; then
        skip "$1 SIG$s1 then SIG$s2 ends the process at once" "the first one ended it first"
    else
        [ $rc -eq "$want" ]
        t $? "$1: SIG$s1 then SIG$s2 ends the process at once (exit $rc, want $want)"
    fi
}
second INT INT 130 run "$PRESETS/combined-load.ini" --set fidelity.model=dynamic --json
second INT TERM 143 sweep "$PRESETS/7008C.ini" --grid operating.axial_load_N=50:1000:4000 \
    --jsonl "$TMP/second.jsonl"

# 4. Without a terminal (and without ACBB_PROGRESS) nothing is drawn.
ACBB_PROGRESS= "$ACBB" run "$PRESETS/7008C.ini" --quiet 2>"$TMP/err"
code $? 0 "a plain run still converges"
! grep -q $'\r' "$TMP/err"
t $? "no progress line when stderr is not a terminal"

tap_done
