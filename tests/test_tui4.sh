#!/bin/sh
# What-if at scale from the TUI (TAP, tmux; helpers in test_tui_lib.sh):
# the Sweep screen sweeps a key of the open scene in the background and
# shows each point as `acbb run --set` computes it; a long sweep cancels
# promptly and says so; the Sensitivity screen's sorted table starts with
# the input `acbb sensitivity --json` puts first. The whole session runs
# without colour in the C locale at 80x24.
# Usage: test_tui4.sh PATH/TO/acbb   (cwd = repo root)
set -u
. "$(dirname "$0")/test_tui_lib.sh"

cp "$ROOT/presets/7008C.ini" "$TMP/copy.ini"
# A number of the run's JSON by its jq path (python3 when jq is missing).
json_num() { # jq-path
    if command -v jq >/dev/null 2>&1; then jq -r "$1"
    else python3 -c "import json,sys; d=json.load(sys.stdin); print(eval('d' + sys.argv[1]))" "$2"; fi
}
typekeys() { $T send-keys -t "$S" -l "$1"; }

start "env NO_COLOR=1 LC_ALL=C LANG=C" sess copy.ini
wait_for "copy.ini" && wait_for "Idle at ambient"
ok $? "launch (NO_COLOR, C locale, 80x24)"

# ---- the Sweep screen ----
keys 9
wait_for "[9 Sweep]" && wait_for "r/Enter sweeps the edited scene"
ok $? "9 opens the Sweep screen, idle"
keys s C-u
typekeys "axial_lo"
keys Tab
wait_for "sweep key (Tab completes): operating.axial_load_N_"
ok $? "Tab completes axial_lo to operating.axial_load_N"
keys Enter e C-u
typekeys "200:1000:3"
keys Enter
wait_for "Sweep operating.axial_load_N = 200:1000:3   metric: total loss [W]"
ok $? "the key, the range and the default metric (total loss) are shown"
keys r
wait_for "done: 3/3 points, 0 failed" 20
ok $? "the 3-point sweep finishes in the background"
miss=""
for v in 200 600 1000; do
    want=$("$ACBB" run "$TMP/copy.ini" --set operating.axial_load_N=$v --json |
           json_num .losses_W.total '["losses_W"]["total"]')
    want=$(printf '%.6g' "$want")
    got=$(screen | sed -n "s/.* $v  *\([-0-9.e+]*\) *\$/\1/p" | tail -1)
    [ -n "$got" ] && [ "$got" = "$want" ] || miss="$miss $v:'$got'!='$want'"
done
[ -z "$miss" ]
ok $? "each point's total loss equals acbb run --set's to display precision ($miss)"
screen | grep -q "^60 W\|[0-9] W " && screen | grep -q " N *\$"
ok $? "the chart has y ticks in W and the x unit N"

# A long sweep at the dynamic level (seconds per point) cancels promptly.
keys 5
wait_for "Enter edit"
goto_field fidelity.model
# A switch the edited scene cannot feel is said, as the CLI's note says it.
keys Enter C-u
typekeys "static"
keys Enter
wait_for "note: effects.centrifugal = on has no effect"
ok $? "the editor says centrifugal does nothing at the static level"
keys Enter C-u
typekeys "dynamic"
keys Enter
wait_for "copy.ini*"
# 200 points (the most the screen takes), about half a CPU second each:
# the sweep is still running when x arrives on any machine (20 points
# took a few seconds, and a late x could find them done).
keys 9 e C-u
typekeys "200:1000:200"
keys Enter r
wait_for "/200 points" 10
t0=$(date +%s)
keys x
wait_for "cancelled after"
ok $? "x cancels a 200-point dynamic sweep and says cancelled ($(($(date +%s) - t0)) s, reported only)"
line=$(screen | grep "cancelled after" | head -1)
done_n=$(printf '%s' "$line" | sed -n 's/.*cancelled after \([0-9]*\) of 200.*/\1/p')
[ -n "$done_n" ] && [ "$done_n" -lt 200 ]
ok $? "the cancelled sweep ran fewer than 200 points ($line)"

# ---- the Sensitivity screen (the preset again: u u undoes both edits) ----
keys u u 0
wait_for "[0 Sensitivity]" && wait_for "r/Enter runs it on the edited scene"
ok $? "0 opens the Sensitivity screen, idle"
keys r
wait_for "sensitivity done" 60
ok $? "the sensitivity run finishes in the background"
top=$("$ACBB" sensitivity "$TMP/copy.ini" --metric losses_W.total --json | json_num '.inputs[0].key' '["inputs"][0]["key"]')
eff=$("$ACBB" sensitivity "$TMP/copy.ini" --metric losses_W.total --json | json_num '.inputs[0].effect' '["inputs"][0]["effect"]')
row=$(screen | sed -n '/^input  *at low  *at high  *effect/{n;p;}')
name=$(printf '%s' "$row" | awk '{print $1}')
case "$top" in *"$name") nm=0 ;; *) nm=1 ;; esac
[ -n "$name" ] && [ $nm -eq 0 ] && [ "$(printf '%s' "$row" | awk '{print $4}')" = "$(printf '%.3g' "$eff")" ]
ok $? "the top row is acbb sensitivity's first input with its effect ($top $eff; row: $row)"
printf '%s' "$row" | grep -q -- '-|=' && screen | grep -q "low -|= high"
ok $? "the tornado: the top input's low end left of the base value, its high end right"
[ "$(screen | awk 'length > 80' | wc -l)" -eq 0 ]
ok $? "no line wider than 80 columns"

# ---- help ----
keys '?'
wait_for "Keys (j/k scroll"
keys / c a n c e l Space t h e Space s w e e p Enter
wait_for "cancel the sweep"
ok $? "the help lists the Sweep screen's keys"
keys / T E Space - Space W T E Space o n Enter
wait_for "metric TE - WTE on/off"
ok $? "the help lists the Sensitivity screen's keys"
keys Escape q
wait_file "$TMP/sess" 10
[ "$(cat "$TMP/sess" 2>/dev/null)" = "EXIT=0" ]
ok $? "q quits with exit 0"

echo "1..$n"
[ "$failed" -eq 0 ]
