#!/usr/bin/env bash
# The TUI's Spindle screen (issue 31; TAP, tmux, 80x24, no colour): a
# bearing scene gets one line saying how to open a spindle; the spindle
# preset draws its shaft with both sets, runs to convergence with the nose
# drift, stiffness and preloads of `acbb run --json`, every row inside 80
# columns, and g exports the drift over time and the temperature along the axis.
# Usage: test_spindle_tui.sh PATH/TO/acbb   (cwd = repo root)
. "$(dirname "$0")/test_tui_lib.sh"

cp "$ROOT/presets/7008C.ini" "$TMP/one.ini"
TUI_ARGS="--pace 0" start "env NO_COLOR=1" sp1 one.ini
wait_for "Idle at ambient"
keys D
wait_for "Not a spindle. Open one: o (presets), or acbb tui presets/spindle-motor-DBT.ini"
ok $? "D on a bearing scene: one line naming a spindle preset"
[ "$(screen | grep -c '#####')" -eq 0 ] && ! screen | grep -q 'nose drift'
ok $? "and no empty shaft or side block drawn"
keys q
wait_file "$TMP/sp1" 5

cp "$ROOT/presets/spindle-motor-DBT.ini" "$TMP/sp.ini"
TUI_ARGS="--pace 0" start "env NO_COLOR=1 LC_ALL=C" sp2 sp.ini
wait_for "Idle at ambient"
keys D
wait_for "Spindle: shaft "
ok $? "D opens the Spindle screen of the spindle preset"
# 330 mm over the picture's 46 columns from column 8: the front DBT at
# 50 mm centred on column 8 + 6, the rear DB at 275 mm from 8 + 38.
screen | grep -q '^nose -> #' && screen | grep -Eq '^sets {9}>>< {30}>< '
r=$?; [ $r -eq 0 ] || show; ok $r "the shaft drawn from the nose, the DBT and DB sets at the columns of their x"
keys r
wait_for "converged" 300
screen | grep -Eq 'nose drift +[-+][0-9]+\.[0-9]+ um' && ! screen | grep -Eiq 'nose drift +[-+]?(nan|inf)'
r=$?; [ $r -eq 0 ] || show; ok $r "converged: a finite nose drift in um"
# The same converged state as the CLI's: its JSON, printed as the screen prints it.
"$ACBB" run "$TMP/sp.ini" --json >"$TMP/sp.json" 2>/dev/null
jnum() { jq -r "$1" "$TMP/sp.json"; }
want_d=$(printf '%+.2f' "$(jnum .spindle.nose_drift_um)")
want_k=$(printf '%.1f' "$(jnum .spindle.nose_stiffness_N_per_um)")
want_f=$(printf '%.1f' "$(jnum '.spindle.sets[0].preload_N')")
want_r=$(printf '%.1f' "$(jnum '.spindle.sets[1].preload_N')")
got_d=$(screen | sed -n 's/.*nose drift *\([-+][0-9.]*\) um.*/\1/p')
got_k=$(screen | sed -n 's/.*nose k rad *\([0-9.]*\) N\/um.*/\1/p')
got_f=$(screen | sed -n 's/.*front preload *\([-0-9.]*\) N.*/\1/p')
got_r=$(screen | sed -n 's/.*rear  preload *\([-0-9.]*\) N.*/\1/p')
[ -n "$got_d" ] && [ "$got_d" = "$want_d" ] && [ "$got_k" = "$want_k" ]
r=$?; [ $r -eq 0 ] || show
ok $r "nose drift $got_d um and radial stiffness $got_k N/um = acbb run --json ($want_d, $want_k)"
[ -n "$got_f" ] && [ "$got_f" = "$want_f" ] && [ "$got_r" = "$want_r" ]
ok $? "the sets' preloads $got_f and $got_r N = acbb run --json ($want_f, $want_r)"
# the chart's legend gives its last point: the converged drift
screen | grep -Eq '^shaft C +[0-9]+\.[0-9]' && screen | grep -qF "Nose drift (axial) [um]  nose drift ${got_d#+}"
r=$?; [ $r -eq 0 ] || show; ok $r "the temperature along the shaft and the drift-over-time chart ending at the drift"
[ "$(screen | sed 's/ *$//' | awk 'length > 80' | wc -l)" -eq 0 ]
ok $? "nothing drawn past 80 columns"
if command -v gnuplot >/dev/null 2>&1; then
    keys g
    wait_for "wrote spindle_drift and spindle_temperature (.png .svg) to ./acbb-plots/"
    ok $? "g exports the drift and the axial temperature"
    grep -q "<svg" "$TMP/acbb-plots/spindle_temperature.svg" && [ -s "$TMP/acbb-plots/spindle_drift.png" ]
    ok $? "as SVG and PNG"
fi
keys q
wait_file "$TMP/sp2" 5

echo "1..$n"
[ "$failed" -eq 0 ]
