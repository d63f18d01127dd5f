#!/bin/sh
# The TUI's Run screen shows a [schedule]'s progress on its status line
# (row k/N and the speed there), from idle to the end of the run (TAP,
# tmux; helpers in test_tui_lib.sh). Usage: test_schedule_tui.sh PATH/TO/acbb
set -u
. "$(dirname "$0")/test_tui_lib.sh"

cp "$ROOT/presets/run-in-ramp.ini" "$TMP/copy.ini"
TUI_ARGS="--pace 0" start "env NO_COLOR=1 LC_ALL=C LANG=C" sess copy.ini
wait_for "Idle at ambient"
ok $? "launch on run-in-ramp.ini"
screen | tr -s ' \n' ' ' | grep -q "Schedule row 1/6, 0 rpm\."
ok $? "idle: the status line says schedule row 1/6 at 0 rpm"
keys r
# Wait for the run's end, not for "done.": the status line says "Schedule
# row 6/6, 16000 rpm, done." as soon as the last row is reached, while the
# run still heats (q then asks before quitting a running run).
wait_for "Steady state:" 120
ok $? "the run ends in steady state"
screen | tr -s ' \n' ' ' | grep -q "Steady state: thermal steady state after [0-9]* steps Schedule row 6/6, 16000 rpm, done\."
ok $? "steady state at row 6/6, 16000 rpm"
keys q
wait_file "$TMP/sess" 60
[ "$(cat "$TMP/sess" 2>/dev/null)" = "EXIT=0" ]
ok $? "q quits with exit 0"

echo "1..$n"
[ "$failed" -eq 0 ]
