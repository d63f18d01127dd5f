#!/bin/sh
# Issue 29 items 2 and 3 (TAP, tmux, 80x24): every screen's results belong
# to the scene and the key they were run on. An edit hides them until
# undone or rerun. A sweep's points are not
# shown under another key's heading; opening another preset clears the
# TE/WTE comparison, the sweep and the sensitivity analysis of the last
# one; q asks while any background work runs, naming it. The key hints
# come back once the worker took a command (not hidden for a whole run).
# Usage: test_tui_scene.sh PATH/TO/acbb   (cwd = repo root)
set -u
. "$(dirname "$0")/test_tui_lib.sh"

cp "$ROOT/presets/7008C.ini" "$TMP/copy.ini"
TUI_ARGS="--pace 0" start "env NO_COLOR=1" sc copy.ini
wait_for "Idle at ambient"
keys r
wait_for "100% done" && wait_for "r run  space pause  x stop"
ok $? "once the run is under way the key hints are back (issue 29 item 6)"
keys 9 s C-u operating.axial_load_N Enter e C-u 200:1000:3 Enter r
wait_for "done: 3/3 points, 0 failed"
ok $? "a 3-point sweep of the axial load finishes"
keys 5
wait_for "Enter edit"
goto_field operating.radial_load_N
keys Enter C-u 13 Enter
wait_for "[modified]"
keys 9
wait_for "(the last result is hidden: the scene was edited" && ! screen | grep -q "done: 3/3"
ok $? "an edit of the scene hides the sweep run on the scene before it"
keys u
wait_for "done: 3/3 points, 0 failed"
ok $? "undo brings it back"
keys s C-u operating.radial_load_N Enter
wait_for "Sweep operating.radial_load_N" && wait_for "(no sweep of this key and range yet: r runs it)" &&
    ! screen | grep -q "done: 3/3" && ! screen | grep -q "^ *1000 "
ok $? "another key: the axial load's points are no longer shown under its heading"
keys t
wait_for "TE vs WTE: the edited scene"
wait_until sh -c "$T capture-pane -p -t $S | grep -q '^status  *[a-z]*  *[a-z]*' &&
    ! $T capture-pane -p -t $S | grep -q '^status .*running'"
ok $? "t runs the TE/WTE comparison to its end"
# The sensitivity analysis must still run when q is pressed: at the
# quasi-dynamic level its 47 runs end in about 0.1 s, and on 7008C's own
# loads at the dynamic level in a few seconds on a machine with many
# cores, so it runs combined-load's point (radial 600 N, axial 250 N) at
# the dynamic level: about 500 steady iterations, seconds of CPU a run,
# minutes in all (opening another preset cancels it below).
keys 5
wait_for "Enter edit"
goto_field operating.radial_load_N
keys Enter C-u 600 Enter
wait_for "[modified]"
goto_field operating.axial_load_N
keys Enter C-u 250 Enter
wait_until sh -c "$T capture-pane -p -t $S | grep -q 'axial_load_N  *250'"
goto_field fidelity.model
keys Enter C-u dynamic Enter
wait_until sh -c "$T capture-pane -p -t $S | grep -q 'model  *dynamic'"
keys 0 r
wait_for "running "
keys q
wait_for "The sensitivity analysis is in progress. Quit and lose it? y = quit, n = stay"
ok $? "q while the sensitivity analysis runs asks, naming it"
keys n
wait_for "not quitting: the sensitivity analysis goes on"
ok $? "n: it goes on"
keys o p
wait_for "open preset: "
keys "$ROOT/presets/hertz-contact.ini" Enter
wait_for "Unsaved edits. Discard them" && keys y # the dynamic-level edit above
wait_for "opened $ROOT/presets/hertz-contact.ini"
ok $? "another preset opened while the sensitivity analysis runs"
keys 0
wait_for "r/Enter runs it on the edited scene" && ! screen | grep -q "running [0-9]"
ok $? "Sensitivity: the last preset's run is cancelled and gone"
keys 6
wait_for "Press t to run both variants to steady state."
ok $? "TE/WTE: the last preset's comparison is gone"
keys 9
wait_for "r/Enter sweeps the edited scene in the background" && ! screen | grep -q "done: 3/3"
ok $? "Sweep: no result of the last preset"
keys q
wait_file "$TMP/sc"
grep -q EXIT=0 "$TMP/sc"
ok $? "q with nothing running quits at once"
echo "1..$n"
[ $failed -eq 0 ]
