#!/bin/sh
# Issue 29 item 8 (TAP, tmux, 80x24): g on the Sweep and Sensitivity
# screens exports their own chart after a finished run, and a TUI export
# never overwrites an earlier one: the second set of plots is numbered
# (temperature-2.png), the message says so and both are kept.
# Usage: test_tui_export.sh PATH/TO/acbb   (cwd = repo root)
set -u
. "$(dirname "$0")/test_tui_lib.sh"
if ! command -v gnuplot >/dev/null 2>&1; then
    echo "1..0 # SKIP gnuplot is not installed"
    exit 0
fi

cp "$ROOT/presets/7008C.ini" "$TMP/qs.ini"
"$ACBB" edit "$TMP/qs.ini" --set fidelity.model=quasi-static >/dev/null 2>&1
TUI_ARGS="--pace 0" start "env NO_COLOR=1" ex qs.ini
wait_for "Idle at ambient"
keys r
wait_for "100% done"
keys g
wait_for "wrote 10 plots (PNG+SVG) to ./acbb-plots/"
ok $? "g exports the run's plots"
keys g
wait_for "wrote 10 plots (PNG+SVG) to ./acbb-plots/ named *-2 (earlier kept)"
ok $? "g again: numbered files, said so"
[ -s "$TMP/acbb-plots/temperature.png" ] && [ -s "$TMP/acbb-plots/temperature-2.png" ] &&
    [ -s "$TMP/acbb-plots/history-loads-2.svg" ]
ok $? "both exports are kept side by side"
keys 9 s C-u operating.axial_load_N Enter e C-u 200:1000:3 Enter r
wait_for "done: 3/3 points, 0 failed"
keys g
wait_for "wrote ./acbb-plots/sweep.png and ./acbb-plots/sweep.svg"
ok $? "Sweep: g exports the sweep's chart after the run"
grep -q "<svg" "$TMP/acbb-plots/sweep.svg"
ok $? "as SVG (and PNG)"
keys 0 r
wait_for "done in "
keys g
wait_for "wrote ./acbb-plots/sensitivity.png and ./acbb-plots/sensitivity.svg"
ok $? "Sensitivity: g exports the tornado chart after the run"
keys g
wait_for "wrote ./acbb-plots/sensitivity-2.png and ./acbb-plots/sensitivity-2.svg"
ok $? "and a second export does not overwrite the first"
keys q
wait_file "$TMP/ex"
echo "1..$n"
[ $failed -eq 0 ]
