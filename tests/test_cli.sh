#!/bin/sh
# End-to-end tests of the acbb CLI (TAP). $1 = path of the acbb binary,
# $2 = its meson build directory (optional: the install tests need it);
# cwd = repository root. Needs jq. Every assertion compares the CLI's output
# with an independent expectation: conservation (loss sum, energy balance),
# exact messages and exit codes, or the seed's qualitative results (MODEL.md 12).
set -u

ACBB=${1:?usage: test_cli.sh path/to/acbb [BUILDDIR]}
BUILD=${2:-}
PRESET=presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-cli.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
# The user's own preset directory must not change what the tests see.
XDG_CONFIG_HOME="$TMP/xdg"
export XDG_CONFIG_HOME

. "$(dirname "$0")/tap.sh"

# ---- run --json at the seed's base point ----
"$ACBB" run "$PRESET" --json >"$TMP/run.json" 2>"$TMP/err"
code $? 0 "run $PRESET --json converges"
jqt "$TMP/run.json" '.status == "converged"' "json status is converged"
jqt "$TMP/run.json" '.losses_W | ((.shear + .slip + .spin + .rolling + .drag) - .total | abs) <= 1e-9 * .total' \
    "losses: total equals the sum of the five (1e-9 rel)"
jqt "$TMP/run.json" '.losses_W | [.shear, .slip, .spin, .rolling, .drag] | all(. >= 0)' \
    "losses: all five are >= 0"
jqt "$TMP/run.json" '.losses_W.total > 0' "losses: total > 0 at 15000 rpm"
jqt "$TMP/run.json" '.temperature_C.outer_ring > 26' "outer ring warmer than the 26 C ambient"
jqt "$TMP/run.json" '(.balls | length) == 21' "21 balls reported"
jqt "$TMP/run.json" '.energy_W | ((.in - .out) | abs) <= 1e-3 * .in' \
    "energy balance: heat in equals heat out within 0.1 %"
jqt "$TMP/run.json" '(.temperature_C.nodes | length) > 0 and ([.temperature_C.nodes[] | . >= 26 - 1e-6] | all)' \
    "every node temperature >= ambient"
jqt "$TMP/run.json" '.expansion_um | ((.inner_ring - .inner_thermal - .inner_centrifugal) | abs) <= 1e-6 * (.inner_ring | abs) + 1e-9' \
    "expansion: inner_ring = inner_thermal + inner_centrifugal"
jqt "$TMP/run.json" '.scene.keys["operating.inner_speed_rpm"] == 15000 and .scene.keys["operating.axial_load_N"] == 1000 and .scene.keys["effects.thermal_expansion"] == "on"' \
    "scene echoes the preset operating point (15000 rpm, 1000 N, TE)"
jqt "$TMP/run.json" '[.balls[] | .Qo_N >= .Qi_N * 0.5 and .alpha_i_deg > 0 and .alpha_o_deg > 0] | all' \
    "balls: positive contact angles, sane Qo"

# At the quasi-dynamic level the inner-race tractions carry part of the
# axial load too, so the normal forces alone balance it only up to the
# friction available (boundary friction mu_bd = 0.1 times the loads).
jqt "$TMP/run.json" '([.balls[] | .Qi_N * (.alpha_i_deg * 3.141592653589793 / 180 | sin)] | add) as $fx
    | ([.balls[] | .Qi_N] | add) as $q
    | (($fx - .scene.keys["operating.axial_load_N"]) | abs) <= 0.1 * $q and $fx > 0.9 * .scene.keys["operating.axial_load_N"]' \
    "inner-ring equilibrium: sum Qi sin(alpha_i) = axial load within the friction bound"

# ---- plain summary ----
"$ACBB" run "$PRESET" >"$TMP/run.txt" 2>"$TMP/err"
code $? 0 "plain run exits 0"
grep -q "^status  *converged" "$TMP/run.txt"
t $? "plain output names the status"
has "$TMP/run.txt" "all 21 balls" "identical balls collapse to one row"
awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/run.txt"
t $? "plain output fits 80 columns"

# Every shipped preset's summary fits 80 columns: sets (the set and
# stiffness lines), spindles, the branches block of a rigid preload (its
# table was 92 columns wide, the set lines up to 108).
wide=""
for p in "$(dirname "$PRESET")"/*.ini; do
    "$ACBB" run "$p" >"$TMP/p.txt" 2>/dev/null
    awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/p.txt" || wide="$wide $(basename "$p")"
done
[ -z "$wide" ]
t $? "every preset's summary fits 80 columns${wide:+ (wider:$wide)}"

# combined load: balls differ, so one row pair per ball; radial equilibrium
"$ACBB" run "$PRESET" --set operating.radial_load_N=300 >"$TMP/rad.txt" 2>"$TMP/err"
code $? 0 "combined load (1000 N axial, 300 N radial) exits 0"
[ "$(grep -c '^ball [0-9]' "$TMP/rad.txt")" -eq 21 ]
t $? "combined load: 21 per-ball rows"
awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/rad.txt"
t $? "combined-load output fits 80 columns"
"$ACBB" run "$PRESET" --json --set operating.radial_load_N=300 >"$TMP/rad.json" 2>"$TMP/err"
jqt "$TMP/rad.json" '([.balls[] | .Qi_N * (.alpha_i_deg * 3.141592653589793 / 180 | cos)
    * (.psi_deg * 3.141592653589793 / 180 | cos)] | add) as $fr
    | (($fr - .scene.keys["operating.radial_load_N"]) | abs) <= 1e-3 * .scene.keys["operating.axial_load_N"]' \
    "radial equilibrium: sum Qi cos(alpha_i) cos(psi) = radial load"
jqt "$TMP/rad.json" '([.balls[].Qi_N] | max) > ([.balls[].Qi_N] | min) * 1.01' \
    "radial load spreads the ball loads"

# ---- CSV, in the same run as the JSON ----
"$ACBB" run "$PRESET" --json --csv "$TMP/run.csv" >"$TMP/csv.json" 2>"$TMP/err"
code $? 0 "run --json --csv exits 0"
[ ! -e "$TMP/run.csv.tmp" ] && [ -s "$TMP/run.csv" ]
t $? "csv written and the .tmp renamed away"
head -n 1 "$TMP/run.csv" | grep -q -x -F 'iteration,time_s,dt_s,temperature_C.outer_ring,temperature_C.inner_ring,temperature_C.ball,losses_W.shear,losses_W.slip,losses_W.spin,losses_W.rolling,losses_W.drag,losses_W.cage,losses_W.ehl_rolling,losses_W.churning,losses_W.total,balls[0].Qi_N,balls[0].Qo_N,balls[0].alpha_i_deg,balls[0].alpha_o_deg,expansion_um.ball,expansion_um.inner_ring,expansion_um.outer_ring,residual_K_s,ring.delta_x_um,ring.delta_z_um,ring.tilt_y_mrad,balls[0].film_i_um,balls[0].film_o_um,balls[0].hmin_i_um,balls[0].hmin_o_um,squeeze_um.inner_thermal,squeeze_um.inner_centrifugal,squeeze_um.outer,squeeze_um.ball,squeeze_um.net,life.L10r_h,life.Lnmr_h,life.a_iso,life.kappa,life.s0_min'
t $? "csv header row"
iters=$(jq '.iterations' "$TMP/csv.json")
rows=$(($(wc -l <"$TMP/run.csv") - 1))
[ "$rows" -eq "$iters" ] || [ "$rows" -eq $((iters + 1)) ]
t $? "csv rows ($rows) == iterations ($iters) + 0 or 1"
awk -F, 'NR > 2 && $1 <= prev { bad = 1 } NR > 1 { prev = $1 } END { exit bad }' "$TMP/run.csv"
t $? "csv iteration column strictly increasing"
awk -F, 'NR > 1 && NF != 40 { bad = 1 } END { exit bad }' "$TMP/run.csv"
t $? "csv rows have 40 fields"
last_T=$(tail -n 1 "$TMP/run.csv" | cut -d, -f4)
jq -e --argjson T "$last_T" 'def abs: if . < 0 then -. else . end;
    ((.temperature_C.outer_ring - $T) | abs) <= 1e-9 * ($T | abs)' "$TMP/csv.json" >/dev/null 2>&1
t $? "csv last-row T_outer_ring ($last_T) equals the JSON outer_ring"
last_P=$(tail -n 1 "$TMP/run.csv" | cut -d, -f15)
jq -e --argjson P "$last_P" 'def abs: if . < 0 then -. else . end;
    ((.losses_W.total - $P) | abs) <= 1e-9 * ($P | abs)' "$TMP/csv.json" >/dev/null 2>&1
t $? "csv last-row P_total equals the JSON total"
awk -F, 'NR > 1 { s = $7 + $8 + $9 + $10 + $11 + $12 + $13 + $14; d = s - $15; if (d < 0) d = -d;
    if (d > 1e-8 * ($15 < 0 ? -$15 : $15) + 1e-12) bad = 1 } END { exit bad }' "$TMP/run.csv"
t $? "csv: every row's total equals the sum of its eight losses"

# ---- --set ----
"$ACBB" run "$PRESET" --json --set operating.axial_load_N=200 >"$TMP/200.json" 2>"$TMP/err"
code $? 0 "run --set operating.axial_load_N=200 exits 0"
jq -e --slurpfile hi "$TMP/run.json" '.balls[0].Qi_N < $hi[0].balls[0].Qi_N and .scene.keys["operating.axial_load_N"] == 200' \
    "$TMP/200.json" >/dev/null 2>&1
t $? "--set axial 200 N gives a smaller Qi than 1000 N"

"$ACBB" run "$PRESET" --set operating.axial_lod_N=200 >"$TMP/out" 2>"$TMP/err"
code $? 2 "unknown --set key exits 2"
has "$TMP/err" "acbb: --set operating.axial_lod_N=200: " "unknown key message names the edit"
has "$TMP/err" "did you mean" "unknown key message suggests a key"
has "$TMP/err" "axial_load_N" "suggestion is the nearest key"

"$ACBB" run "$PRESET" --set operating.axial_load_N=-5 >"$TMP/out" 2>"$TMP/err"
code $? 2 "out-of-range --set value exits 2"
has "$TMP/err" "acbb: --set operating.axial_load_N=-5: " "range message names the edit"
grep -q -i 'range\|must be\|>=' "$TMP/err"
t $? "range message says what is allowed"
[ ! -s "$TMP/out" ]
t $? "nothing on stdout after a bad --set"

"$ACBB" run "$PRESET" --set operating.axial_load_N >"$TMP/out" 2>"$TMP/err"
code $? 2 "--set without '=' exits 2"

# ---- bad presets ----
"$ACBB" run "$TMP/no-such.ini" >"$TMP/out" 2>"$TMP/err"
code $? 2 "missing preset exits 2"
has "$TMP/err" "cannot open" "missing preset message says cannot open"

bad="$TMP/bad.ini"
if grep -q '^[[:space:]]*ball_diameter_mm[[:space:]]*=' "$PRESET"; then
    sed 's/^[[:space:]]*ball_diameter_mm[[:space:]]*=.*/ball_diameter_mm = -3/' "$PRESET" >"$bad"
else
    sed 's/^\[bearing\].*/&\nball_diameter_mm = -3/' "$PRESET" >"$bad"
fi
line=$(grep -n '^ball_diameter_mm = -3$' "$bad" | cut -d: -f1)
"$ACBB" run "$bad" >"$TMP/out" 2>"$TMP/err"
code $? 2 "preset with ball_diameter_mm = -3 exits 2"
has "$TMP/err" "$bad:$line: bearing.ball_diameter_mm = -3" "message is file:line: bearing.ball_diameter_mm = -3"

# ---- check ----
"$ACBB" check "$PRESET" >"$TMP/out" 2>"$TMP/err"
code $? 0 "check of the seed preset exits 0"
grep -q -x "$PRESET: ok" "$TMP/out"
t $? "check prints 'PRESET: ok'"
"$ACBB" check "$bad" >"$TMP/out" 2>"$TMP/err"
code $? 2 "check of the bad preset exits 2"
has "$TMP/err" "bearing.ball_diameter_mm = -3" "check prints the bad-value message"
"$ACBB" check "$PRESET" --set operating.axial_load_N=0 --set operating.radial_load_N=500 \
    >"$TMP/out" 2>"$TMP/err"
code $? 2 "check of a pure radial scene (ill-posed) exits 2"
grep -q 'axial_load_N' "$TMP/err"
t $? "ill-posed message names the key to change (axial_load_N)"

# ---- exit 3: step limit ----
"$ACBB" run "$PRESET" --json --set thermal.max_steps=3 >"$TMP/ns.json" 2>"$TMP/err"
code $? 3 "step limit reached exits 3"
jqt "$TMP/ns.json" '.status == "not_converged" and .iterations <= 3' \
    "--json still prints the object, status not_converged, <= 3 iterations"
grep -q 'not_converged' "$TMP/err"
t $? "stderr names the status"

# ---- seed conclusion 1 through the CLI (TE vs WTE at 15000 rpm, 1000 N) ----
# The seed says TE raises the contact loads. In this model the sign of the
# change follows the net squeeze of the expansions (ring growths along the
# contact line, ball growth on both contacts); the test checks that, and a
# diagnostic line says whether the seed's claim holds (see the issue notes).
"$ACBB" run "$PRESET" --json --set operating.inner_speed_rpm=15000 \
    --set operating.axial_load_N=1000 --set effects.thermal_expansion=false \
    >"$TMP/wte.json" 2>"$TMP/err"
code $? 0 "WTE run at 15000 rpm, 1000 N exits 0"
jq -e --slurpfile te "$TMP/run.json" '
    ($te[0].expansion_um) as $e
    | (($e.inner_ring - $e.outer_ring) * ($te[0].balls[0].alpha_i_deg * 3.141592653589793 / 180 | cos)
       + 2 * $e.ball) as $squeeze
    | .scene.keys["effects.thermal_expansion"] == "off"
      and (($te[0].balls[0].Qi_N - .balls[0].Qi_N) * $squeeze > 0)' \
    "$TMP/wte.json" >/dev/null 2>&1
t $? "TE - WTE inner load has the sign of the net expansion squeeze (1000 N)"
held=$(jq -r --slurpfile te "$TMP/run.json" \
    'if $te[0].balls[0].Qi_N > .balls[0].Qi_N then "held" else "NOT held" end' "$TMP/wte.json")
echo "# seed conclusion 1 (Qi TE > WTE at 1000 N): $held"

# ---- sweep ----
"$ACBB" sweep "$PRESET" --param operating.axial_load_N --values 200,500,1000 --json \
    >"$TMP/sw.json" 2>"$TMP/err"
code $? 0 "sweep of 3 loads exits 0"
jqt "$TMP/sw.json" 'length == 3 and ([.[].value] == [200, 500, 1000])' "sweep JSON has the 3 points in order"
jqt "$TMP/sw.json" '[.[]."balls[0].Qi_N"] | [range(1; length) as $i | .[$i] > .[$i - 1]] | all' \
    "sweep: Qi increases with the axial load"
# A sweep point is the steady solve: the run's steady state to ~5e-9 (sweep.h).
jq -e --slurpfile one "$TMP/run.json" 'def abs: if . < 0 then -. else . end;
    ((.[2]."losses_W.total" - $one[0].losses_W.total) | abs) <= 1e-8 * .[2]."losses_W.total"' \
    "$TMP/sw.json" >/dev/null 2>&1
t $? "sweep point at 1000 N equals the single run (to 1e-8)"
"$ACBB" sweep "$PRESET" --param operating.axial_load_N --values 200,500,1000 \
    --csv "$TMP/sw.csv" >"$TMP/sw.txt" 2>"$TMP/err"
code $? 0 "sweep --csv exits 0"
[ "$(wc -l <"$TMP/sw.csv")" -eq 4 ]
t $? "sweep CSV: header + 3 rows"
awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/sw.txt"
t $? "sweep table fits 80 columns"
"$ACBB" sweep "$PRESET" --param operating.axial_load_N --values 200,-5 >"$TMP/out" 2>"$TMP/err"
code $? 2 "sweep with a bad value exits 2"
"$ACBB" sweep "$PRESET" --param thermal.max_steps --values 3,2000 --json >"$TMP/sw3.json" 2>"$TMP/err"
code $? 3 "sweep with a failing point exits 3"
jqt "$TMP/sw3.json" 'length == 2 and .[0].status == "not_converged" and .[1].status == "converged"' \
    "failing sweep still prints every point"

# ---- commands and usage ----
"$ACBB" frobnicate >"$TMP/out" 2>"$TMP/err"
code $? 2 "unknown command exits 2"
has "$TMP/err" "usage:" "unknown command prints the usage on stderr"
[ ! -s "$TMP/out" ]
t $? "unknown command prints nothing on stdout"
"$ACBB" --help >"$TMP/out" 2>"$TMP/err"
code $? 0 "--help exits 0"
missing=0
for c in run check sweep study bench presets keys; do
    grep -q "^  $c" "$TMP/out" || missing=1
done
t $missing "usage lists every command"
"$ACBB" run "$PRESET" --bogus >"$TMP/out" 2>"$TMP/err"
code $? 2 "unknown option exits 2"
"$ACBB" keys >"$TMP/keys.txt" 2>"$TMP/err"
code $? 0 "keys exits 0"
has "$TMP/keys.txt" "operating.axial_load_N" "keys lists operating.axial_load_N"
has "$TMP/keys.txt" "bearing.ball_diameter_mm" "keys lists bearing.ball_diameter_mm"
"$ACBB" presets >"$TMP/presets.txt" 2>"$TMP/err"
code $? 0 "presets exits 0"
has "$TMP/presets.txt" "7008C.ini" "presets lists 7008C.ini"

# The sixth loss (MODEL.md 6 iii) is one row of the loss table: switched on,
# it shows in the JSON, the CSV and the text summary with the other five.
"$ACBB" run presets/7008C.ini --set effects.loss_cage=on --json --csv "$TMP/cage.csv" \
    >"$TMP/cage.json" 2>"$TMP/err"
code $? 0 "run with effects.loss_cage=on exits 0"
jq -e 'def abs: if . < 0 then -. else . end; .losses_W.cage > 0 and ((.losses_W.shear
    + .losses_W.slip + .losses_W.spin + .losses_W.rolling + .losses_W.drag + .losses_W.cage
    - .losses_W.total) | abs) < 1e-6' \
    "$TMP/cage.json" >/dev/null
t $? "JSON: cage loss > 0 and the six losses sum to the total"
awk -F, 'NR > 1 && $12 <= 0 { bad = 1 } END { exit bad }' "$TMP/cage.csv"
t $? "CSV: losses_W.cage column positive in every row"
"$ACBB" run presets/7008C.ini --set effects.loss_cage=on >"$TMP/cage.txt" 2>&1
has "$TMP/cage.txt" "cage" "text summary lists the cage loss"
awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/cage.txt"
t $? "text summary with six losses fits 80 columns"

# The extended set (MODEL.md 16): EHL rolling resistance as one more row,
# named in the JSON; the seed set is what the seed preset declares.
"$ACBB" run presets/7008C.ini --set effects.loss_ehl_rolling=on --set lubricant.grade=VG68 \
    --json >"$TMP/ext.json" 2>"$TMP/err"
code $? 0 "run with the extended set exits 0"
jq -e '.loss_set == "extended" and .losses_W.ehl_rolling > 0 and .losses_W.churning == 0
    and .scene.keys["lubricant.grade"] == "VG68"' "$TMP/ext.json" >/dev/null
t $? "JSON: loss_set extended, ehl_rolling > 0, churning 0 with oil-air"
jq -e '.loss_set == "seed" and .losses_W.ehl_rolling == 0' "$TMP/cage.json" >/dev/null
t $? "JSON: the seed preset declares the seed set"
# Physics profiles (issue 25): the run says which it used, in the JSON and
# in the text summary's header; --set physics.profile moves the keys it sets.
jq -e '.profile == "seed"' "$TMP/cage.json" >/dev/null
t $? "JSON: the seed preset's profile is seed"
"$ACBB" run presets/7008C.ini --set physics.profile=reference --set effects.heating=off \
    >"$TMP/ref.txt" 2>"$TMP/ref.err"
code $? 0 "run with --set physics.profile=reference exits 0"
grep -q '^physics  *reference profile' "$TMP/ref.txt" && grep -q 'ehl_roll' "$TMP/ref.txt" &&
    grep -q 'cage' "$TMP/ref.txt" && ! grep -q 'loss_churning' "$TMP/ref.err"
t $? "text: header names the reference profile, its losses listed, no note for its churning"
"$ACBB" run presets/7008C.ini --set effects.loss_ehl_rolling=on --set effects.loss_churning=on \
    --set effects.loss_cage=on >"$TMP/ext.txt" 2>"$TMP/ext.err"
grep -q 'loss_churning = on has no effect here' "$TMP/ext.err"
t $? "churning with oil-air is named as inactive"
awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/ext.txt"
t $? "text summary with eight losses fits 80 columns"
tr -s ' \n' ' ' <"$TMP/keys.txt" | grep -q 'VG2 | VG3 .* VG1500'
t $? "keys lists the ISO VG grades"

# ---- help from the command table ----
"$ACBB" help run >"$TMP/help-run.txt" 2>"$TMP/err"
code $? 0 "help run exits 0"
grep -q '^usage: acbb run PRESET \[--set KEY=VALUE\]\.\.\. \[--json\]' "$TMP/help-run.txt"
t $? "help run shows run's synopsis"
missing=0
for o in --set --json --csv --quiet --plot; do
    grep -q "^  $o" "$TMP/help-run.txt" || missing=1
done
t $missing "help run describes every option run accepts"
! grep -q -- '--param' "$TMP/help-run.txt"
t $? "help run does not list sweep's --param"
"$ACBB" run --help >"$TMP/run-help.txt" 2>"$TMP/err"
code $? 0 "run --help exits 0"
cmp -s "$TMP/help-run.txt" "$TMP/run-help.txt"
t $? "run --help prints the same text as help run"
"$ACBB" help bench >"$TMP/help-bench.txt" 2>"$TMP/err"
[ "$(grep -c '^usage: acbb bench' "$TMP/help-bench.txt")" -eq 2 ]
t $? "help bench shows bench speed and bench accuracy"
awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/help-run.txt" "$TMP/help-bench.txt" "$TMP/out"
t $? "help texts fit 80 columns"
"$ACBB" help nosuch >"$TMP/out" 2>"$TMP/err"
code $? 2 "help of an unknown command exits 2"
# A failed stdout is exit 4 for the help texts as for every other command
# (`keys` is the reference: it always was).
if [ -w /dev/full ]; then
    for args in "help" "help --man" "help run" "--help" "--version" "keys"; do
        # shellcheck disable=SC2086
        "$ACBB" $args >/dev/full 2>"$TMP/err"
        code $? 4 "acbb $args onto /dev/full"
        has "$TMP/err" "cannot write to stdout" "acbb $args onto /dev/full says why"
    done
else
    skip "help onto /dev/full" "no writable /dev/full"
fi

# Help, usage and the man page come from the command table (issue 16): every
# row of the table in cli/main.c is in `acbb help` and in `acbb help --man`
# (what meson installs as acbb.1), every option row of cli/args.c in the
# man page; tui and report print their usage from their rows too.
sed -n -E 's/^    \{ "([a-z]+)", (NULL|"([a-z]+)"),.*/\1 \3/p' cli/main.c | sed 's/ $//' \
    >"$TMP/rows.txt"
"$ACBB" help >"$TMP/help.txt" 2>"$TMP/err"
"$ACBB" help --man >"$TMP/acbb.1" 2>"$TMP/err"
code $? 0 "help --man exits 0"
missing=""
while read -r name sub; do
    cmd="$name${sub:+ $sub}"
    grep -q "^  $cmd" "$TMP/help.txt" || missing="$missing help:$cmd"
    grep -q -F "\\fBacbb $cmd\\fR" "$TMP/acbb.1" || missing="$missing man:$cmd"
done <"$TMP/rows.txt"
nrows=$(wc -l <"$TMP/rows.txt")
[ "$nrows" -ge 18 ] && [ -z "$missing" ]
t $? "every command of the table ($nrows) is in acbb help and the man page${missing:+ (missing:$missing)}"
# Over SSH at 80x24: the overview and every command's help fit 80 columns.
wide=""
awk 'length($0) > 80' "$TMP/help.txt" | grep -q . && wide="$wide overview"
while read -r name sub; do
    "$ACBB" help $name $sub 2>&1 | awk 'length($0) > 80' | grep -q . && wide="$wide $name${sub:+-$sub}"
done <"$TMP/rows.txt"
[ -z "$wide" ]
t $? "acbb help and every acbb help COMMAND fit 80 columns${wide:+ (not:$wide)}"
opts=$(sed -n -E 's/^    \[CLI_OPT_[A-Z_]+\] = \{ "([a-z-]+)".*/\1/p' cli/args.c)
missing=""
nopts=0
for o in $opts; do
    nopts=$((nopts + 1))
    roff=$(printf '%s' "--$o" | sed 's/-/\\-/g')
    grep -q -F "\\fB$roff\\fR" "$TMP/acbb.1" || missing="$missing --$o"
done
[ "$nopts" -ge 30 ] && [ -z "$missing" ]
t $? "every option of the table ($nopts) is in the man page${missing:+ (missing:$missing)}"
grep -q '^\.SH COMMANDS' "$TMP/acbb.1" && grep -q '^\.SH EXIT STATUS' "$TMP/acbb.1" &&
    grep -q 'cancelled by SIGINT' "$TMP/acbb.1"
t $? "the man page has COMMANDS and EXIT STATUS (with the cancel)"
if command -v groff >/dev/null 2>&1; then
    groff -man -Tutf8 -ww "$TMP/acbb.1" 2>"$TMP/groff.err" >/dev/null
    [ ! -s "$TMP/groff.err" ]
    t $? "groff renders the man page without a warning"
else
    skip "groff renders the man page without a warning" "no groff"
fi
for c in tui report; do
    "$ACBB" $c --help >"$TMP/c-help.txt" 2>"$TMP/err"
    "$ACBB" help $c >"$TMP/help-c.txt" 2>&1
    grep -q "^usage: acbb $c " "$TMP/c-help.txt" && cmp -s "$TMP/c-help.txt" "$TMP/help-c.txt"
    t $? "$c --help is its table row's usage, as help $c"
done
"$ACBB" tui --pace fast >"$TMP/out" 2>"$TMP/err"
code $? 2 "tui --pace fast exits 2 (parsed by the table, checked by the TUI)"
"$ACBB" report "$PRESET" --md >"$TMP/out" 2>"$TMP/err"
code $? 2 "report --md without a value exits 2"
has "$TMP/err" "option needs a value: --md" "the one parser says so"
# A bad --inputs key is refused before the study runs (issue 28 item 13:
# it used to be found after the whole study): exit 2, no report on
# stdout, no --md file, and no "running the study" progress note first.
ACBB_PROGRESS=1 "$ACBB" report "$PRESET" --inputs materials.ball_E_GPa --md "$TMP/rob.md" \
    >"$TMP/out" 2>"$TMP/err"
code $? 2 "report --inputs with a key that is not an uncertain input exits 2"
[ ! -e "$TMP/rob.md" ] && [ ! -s "$TMP/out" ]
t $? "no report on stdout, no --md file"
has "$TMP/err" "report: --inputs: materials.ball_E_GPa is not an uncertain input" "naming the key"
! grep -q "running the study" "$TMP/err"
t $? "and nothing runs first (no study progress on stderr)"

# ---- unknown and misplaced options ----
"$ACBB" run "$PRESET" --josn >"$TMP/out" 2>"$TMP/err"
code $? 2 "misspelt option --josn exits 2"
has "$TMP/err" "unknown option --josn; did you mean --json?" "the message suggests --json"
"$ACBB" sweep "$PRESET" --parma operating.axial_load_N --values 1 >"$TMP/out" 2>"$TMP/err"
code $? 2 "misspelt --parma exits 2"
has "$TMP/err" "did you mean --param?" "the message suggests --param"
"$ACBB" run "$PRESET" --zzzzzz >"$TMP/out" 2>"$TMP/err"
code $? 2 "a far-off option exits 2"
! grep -q "did you mean" "$TMP/err"
t $? "no suggestion when nothing is close"
"$ACBB" check "$PRESET" --json >"$TMP/out" 2>"$TMP/err"
code $? 2 "an option of another command exits 2"
has "$TMP/err" "--json is not an option of this command" "the message says so"
"$ACBB" run "$PRESET" --json=yes >"$TMP/out" 2>"$TMP/err"
code $? 2 "a value for a flag exits 2"
"$ACBB" run "$PRESET" --csv >"$TMP/out" 2>"$TMP/err"
code $? 2 "a missing option value exits 2"
"$ACBB" chekc "$PRESET" >"$TMP/out" 2>"$TMP/err"
code $? 2 "misspelt command exits 2"
has "$TMP/err" "did you mean 'check'?" "the message suggests check"
"$ACBB" sweep "$PRESET" --param operating.axial_load_N --values 200 --jobs 0 >"$TMP/out" 2>"$TMP/err"
code $? 2 "--jobs 0 exits 2"
has "$TMP/err" "expected a whole number 1..100000" "the --jobs message gives the range"
# One --jobs bound for every command that takes it (ACBB_CLI_MAX_JOBS):
# 300 passes the parse (the unknown metric after it is what fails), 100001
# is refused with the same range everywhere.
"$ACBB" sensitivity "$PRESET" --jobs 300 --metric nosuch >"$TMP/out" 2>"$TMP/err"
code $? 2 "sensitivity --jobs 300 --metric nosuch exits 2"
has "$TMP/err" "metric 'nosuch' is unknown" "sensitivity accepts --jobs 300 (the metric is refused)"
for cmd in "sweep $PRESET" "sensitivity $PRESET --metric losses_W.total" "study $PRESET" \
           "study seed --out $TMP/nofig" "report $PRESET" "bench speed" \
           "bench accuracy $PRESET --envelope"; do
    # shellcheck disable=SC2086
    "$ACBB" $cmd --jobs 100001 >"$TMP/out" 2>"$TMP/err"
    code $? 2 "$cmd --jobs 100001 exits 2"
    has "$TMP/err" "--jobs 100001: expected a whole number 1..100000" "$cmd: the one --jobs range"
done

# ---- version: the meson project version ----
if [ -n "$BUILD" ] && want=$(meson introspect "$BUILD" --projectinfo 2>/dev/null | jq -r .version) \
        && [ -n "$want" ]; then
    [ "$("$ACBB" --version)" = "acbb $want" ]
    t $? "--version prints acbb $want (meson introspect)"
    [ "$("$ACBB" version)" = "acbb $want" ]
    t $? "version prints acbb $want"
else
    echo "ok $((n += 1)) - --version # SKIP no build directory given"
    echo "ok $((n += 1)) - version # SKIP no build directory given"
fi

# ---- preset names through the search path ----
"$ACBB" check 7008C >"$TMP/out" 2>"$TMP/err"
code $? 0 "check 7008C (a bare name) exits 0"
grep -q -x "presets/7008C.ini: ok" "$TMP/out"
t $? "7008C resolves to presets/7008C.ini in the source tree"
"$ACBB" check 7008C.ini >"$TMP/out" 2>"$TMP/err"
grep -q -x "presets/7008C.ini: ok" "$TMP/out"
t $? "7008C.ini resolves the same way"
"$ACBB" run no-such-preset >"$TMP/out" 2>"$TMP/err"
code $? 2 "an unknown bare preset name exits 2"
has "$TMP/err" "cannot open preset no-such-preset" "the message names it"
has "$TMP/err" "$TMP/xdg/acbb/presets" "the message lists the user directory searched"

# ---- a real install, used from another directory ----
if [ -n "$BUILD" ] && command -v meson >/dev/null 2>&1; then
    # Two tests install from the same build directory (test_cli, test_install_lib):
    # one at a time (both write the build's meson-logs/install-log.txt).
    flock "$BUILD/meson-private/acbb-test-install.lock" \
        meson install -C "$BUILD" --destdir "$TMP/d" --no-rebuild --quiet >"$TMP/inst.log" 2>"$TMP/err"
    code $? 0 "meson install --destdir"
    # meson prints its ERROR lines on stdout
    grep -h -s ERROR "$TMP/inst.log" "$TMP/err" | sed 's/^/# /' | head -n 20
    INST=$(find "$TMP/d" -type f -path '*/bin/acbb' | head -n 1)
    [ -n "$INST" ] && [ -x "$INST" ]
    t $? "the binary is installed (${INST#$TMP/d})"
    PDIR=$(find "$TMP/d" -type d -path '*/share/acbb/presets' | head -n 1)
    [ -n "$PDIR" ] && [ -f "$PDIR/7008C.ini" ] && [ -f "$PDIR/teaching-7node.ini" ]
    t $? "the presets are installed (${PDIR#$TMP/d})"
    MAN=$(find "$TMP/d" -path '*/man1/acbb.1' -type f | head -n 1)
    [ -n "$MAN" ] && cmp -s "$MAN" "$TMP/acbb.1"
    t $? "the man page acbb(1) is installed, as acbb help --man prints it"
    mkdir -p "$TMP/elsewhere" "$TMP/xdg-empty"
    (cd "$TMP/elsewhere" && XDG_CONFIG_HOME="$TMP/xdg-empty" "$INST" presets) \
        >"$TMP/ipresets.txt" 2>"$TMP/err"
    code $? 0 "installed acbb presets exits 0"
    grep -q -F "$PDIR/  (installed)" "$TMP/ipresets.txt"
    t $? "acbb presets lists the installed directory"
    has "$TMP/ipresets.txt" "$TMP/xdg-empty/acbb/presets/  (user, not present)" \
        "acbb presets lists the (empty) user directory first"
    awk -v d="$PDIR/  (installed)" 'index($0, d) == 1 { inside = 1; next } /^$/ { inside = 0 }
        inside && $1 == "7008C.ini" && !/shadowed/ { found = 1 } END { exit !found }' "$TMP/ipresets.txt"
    t $? "acbb presets shows 7008C.ini in the installed directory"
    (cd "$TMP/elsewhere" && XDG_CONFIG_HOME="$TMP/xdg-empty" "$INST" run 7008C --json) \
        >"$TMP/irun.json" 2>"$TMP/err"
    code $? 0 "installed acbb run 7008C --json from another directory"
    jqt "$TMP/irun.json" '.status == "converged"' "it converged"
    jq -e --slurpfile src "$TMP/run.json" 'def abs: if . < 0 then -. else . end;
        ((.losses_W.total - $src[0].losses_W.total) | abs) <= 1e-9 * .losses_W.total' \
        "$TMP/irun.json" >/dev/null 2>&1
    t $? "it ran the installed 7008C (same total loss as the source tree's)"
    # A user preset of the same name shadows the installed one.
    mkdir -p "$TMP/xdg-user/acbb/presets"
    sed 's/^axial_load_N = .*/axial_load_N = 200/' "$PDIR/7008C.ini" >"$TMP/xdg-user/acbb/presets/7008C.ini"
    (cd "$TMP/elsewhere" && XDG_CONFIG_HOME="$TMP/xdg-user" "$INST" run 7008C --json) \
        >"$TMP/urun.json" 2>"$TMP/err"
    code $? 0 "run 7008C with a user preset of that name"
    jqt "$TMP/urun.json" '.status == "converged" and .scene.keys["operating.axial_load_N"] == 200' \
        "the user's 7008C (200 N) shadows the installed one (1000 N)"
    (cd "$TMP/elsewhere" && XDG_CONFIG_HOME="$TMP/xdg-user" "$INST" presets) >"$TMP/upresets.txt" 2>&1
    has "$TMP/upresets.txt" "(shadowed by $TMP/xdg-user/acbb/presets)" \
        "acbb presets marks the installed 7008C.ini as shadowed"
    # issue 26 item 6: `acbb edit 7008C` found the installed preset, shared
    # by every user, and rewrote it.
    cp "$PDIR/7008C.ini" "$TMP/inst-7008C.ini"
    (cd "$TMP/elsewhere" && XDG_CONFIG_HOME="$TMP/xdg-empty" "$INST" edit 7008C \
        --set operating.axial_load_N=300) >"$TMP/out" 2>"$TMP/err"
    code $? 2 "edit of the installed 7008C is refused"
    has "$TMP/err" "is an installed preset" "... saying it is the installed, shared preset"
    has "$TMP/err" "--out FILE" "... with the hint --out"
    cmp -s "$PDIR/7008C.ini" "$TMP/inst-7008C.ini"
    t $? "... and the installed file is unchanged"
    (cd "$TMP/elsewhere" && XDG_CONFIG_HOME="$TMP/xdg-empty" "$INST" edit 7008C \
        --set operating.axial_load_N=300 --out "$TMP/mine.ini") >"$TMP/out" 2>"$TMP/err"
    code $? 0 "edit 7008C --out FILE writes the edited copy"
    grep -q '^axial_load_N = 300$' "$TMP/mine.ini" && cmp -s "$PDIR/7008C.ini" "$TMP/inst-7008C.ini" &&
        [ "$(diff "$PDIR/7008C.ini" "$TMP/mine.ini" | grep -c '^[<>]')" -eq 2 ]
    t $? "... one line changed in the copy, the installed file unchanged"
    # The TUI's save in place (w) of the installed 7008C asks for a file of
    # one's own instead, as `acbb edit` refuses (issue 26 item 6).
    if command -v tmux >/dev/null; then
        TS="tmux -L acbbcli$$ -f /dev/null"
        (cd "$TMP/elsewhere" && $TS new-session -d -s w -x 80 -y 24 \
            "env XDG_CONFIG_HOME=$TMP/xdg-empty NO_COLOR=1 $INST tui 7008C --pace 0; sleep 1")
        pane() { $TS capture-pane -p -t w 2>/dev/null; }
        i=0; while [ $i -lt 600 ] && ! pane | grep -q 'Idle at ambient'; do sleep 0.05; i=$((i + 1)); done
        $TS send-keys -t w w
        i=0; while [ $i -lt 600 ] && ! pane | grep -q 'installed preset, shared by every user: save as'; do
            sleep 0.05; i=$((i + 1)); done
        pane | grep -q 'installed preset, shared by every user: save as'
        t $? "the TUI's w on the installed 7008C asks to save as a file of one's own"
        $TS send-keys -t w Escape q y 2>/dev/null
        $TS kill-server 2>/dev/null
        cmp -s "$PDIR/7008C.ini" "$TMP/inst-7008C.ini"
        t $? "... and the installed file is unchanged"
    else
        echo "ok $((n += 1)) - TUI save of the installed preset # SKIP no tmux"
        echo "ok $((n += 1)) - installed kept # SKIP no tmux"
    fi
else
    for what in "meson install" "binary" "presets" "man page" "presets exits 0" \
        "installed dir" "user dir" "7008C listed" "run exits 0" "converged" "same loss" \
        "user run" "user shadows" "shadow marked" "edit installed" "edit says so" \
        "edit hint" "installed kept" "edit --out" "copy edited" "tui save" "tui kept"; do
        echo "ok $((n += 1)) - install: $what # SKIP no build directory given"
    done
fi

# Every effect is honest: a switch the scene cannot feel is said on stderr
# and listed in the JSON; the new outputs are in the JSON and CSV.
"$ACBB" run presets/7008C.ini --set fidelity.model=static --json >"$TMP/static.json" \
    2>"$TMP/static.err"
code $? 0 "run at the static level exits 0"
has "$TMP/static.err" "effects.centrifugal = on has no effect here" \
    "stderr says the centrifugal switch does nothing at the static level"
jq -e '[.effects_inactive[].effect] == ["centrifugal", "gyroscopic"]' "$TMP/static.json" >/dev/null
t $? "JSON effects_inactive lists centrifugal and gyroscopic at the static level"
# Inputs the scene's network does not have are said too (not only switches).
"$ACBB" run presets/teaching-7node.ini --set surroundings.cap=convective --quiet 2>"$TMP/cap.err"
code $? 0 "7-node run with a convective end cap exits 0"
has "$TMP/cap.err" "surroundings.cap_* has no effect here: fidelity.network = 7 has no end cap" \
    "stderr says the 7-node network has no end cap"
"$ACBB" run presets/7008C.ini --set fidelity.model=static --set thermal.heat_partition=0.2 \
    --json >"$TMP/hp.json" 2>/dev/null
jq -e '[.effects_inactive[].key] == ["effects.centrifugal = on", "effects.gyroscopic = on",
        "thermal.heat_partition"]' "$TMP/hp.json" >/dev/null
t $? "JSON effects_inactive names thermal.heat_partition on the 46-node network"
"$ACBB" check presets/7008C.ini --set materials.cage_expansion_ppm_K=20 2>"$TMP/cage.err" >/dev/null
code $? 0 "check with a changed cage expansion exits 0"
has "$TMP/cage.err" "(materials.cage_*) has no effect here: the model has no cage mechanics" \
    "stderr says the cage's expansion enters nothing"
"$ACBB" keys | grep -A3 '^materials.cage_expansion_ppm_K' | grep -q 'plausible'
[ $? -ne 0 ]; t $? "acbb keys gives the cage's expansion no plausible range (not an uncertain input)"
jq -e '.effects_inactive == [] and .ring.stiffness_axial_N_per_um > 0
    and (.squeeze_um.net - (.squeeze_um.inner_thermal + .squeeze_um.inner_centrifugal
         + .squeeze_um.outer + .squeeze_um.ball) | if . < 0 then -. else . end) < 1e-6
    and .balls[0].hmin_i_um < .balls[0].film_i_um and .work.network_solves > 0' \
    "$TMP/csv.json" >/dev/null
t $? "JSON: ring stiffness, squeeze terms summing to net, hmin < central film, work counters"
head -n 1 "$TMP/run.csv" | grep -q 'residual_K_s,ring\.delta_x_um,.*,squeeze_um\.net,life\.L10r_h,life\.Lnmr_h,life\.a_iso,life\.kappa,life\.s0_min$'
t $? "CSV: ring displacement, film and squeeze columns after residual_K_s"
"$ACBB" run presets/7008C.ini --set effects.heating=off --json >"$TMP/iso.json" 2>"$TMP/err"
code $? 0 "heating off exits 0"
jq -e '.work.network_solves == 0 and .temperature_C.outer_ring == 26' "$TMP/iso.json" >/dev/null
t $? "heating off: no network solve, outer ring at ambient"

# What-if baseline: a saved run's JSON against this run.
"$ACBB" run presets/7008C.ini --baseline "$TMP/csv.json" >"$TMP/same.txt" 2>"$TMP/err"
code $? 0 "run --baseline (same scene) exits 0"
has "$TMP/same.txt" "(no value changed)" "the same scene against its own baseline: nothing changed"
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=500 --baseline "$TMP/csv.json" \
    >"$TMP/what.txt" 2>"$TMP/err"
code $? 0 "run --baseline with an edit exits 0"
grep -q 'operating.axial_load_N  *1000  *500  *-500  *-50.00%' "$TMP/what.txt"
t $? "the edited input is listed with its absolute and relative change"
grep -q '^  losses_W.total .*-' "$TMP/what.txt"
t $? "a lower load lowers the total loss (negative change)"
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=500 --baseline "$TMP/csv.json" \
    --json >"$TMP/what.json" 2>"$TMP/err"
jq -e '[.vs_baseline[] | select(.path == "scene.keys.operating.axial_load_N")][0].change == -500
    and (.losses_W.total > 0)' "$TMP/what.json" >/dev/null
t $? "JSON: the run with a vs_baseline array of changes"
printf 'not json' >"$TMP/bad.json"
"$ACBB" run presets/7008C.ini --baseline "$TMP/bad.json" >/dev/null 2>"$TMP/err"
code $? 2 "a baseline that is not an acbb run JSON: exit 2"
has "$TMP/err" "not the JSON of" "and the message says why"

# Preset files (issue "Nothing lost, nothing overwritten"): text after a
# section header is an error with file:line, not silently dropped; a FIFO
# is refused at once (timeout only turns a hang into a failure).
printf '[operating] axial_load_N = 5000\n[bearing]\nn_balls = 20\n' >"$TMP/hdr.ini"
"$ACBB" check "$TMP/hdr.ini" >"$TMP/out" 2>"$TMP/err"
code $? 2 "check: text after a section header exits 2"
has "$TMP/err" "$TMP/hdr.ini:1: text after the section header [operating]" \
    "message is file:1: text after the section header"
mkfifo "$TMP/fifo.ini"
timeout 60 "$ACBB" check "$TMP/fifo.ini" >"$TMP/out" 2>"$TMP/err"
rc=$?
[ "$rc" -ne 0 ] && [ "$rc" -ne 124 ]
t $? "check of a FIFO fails at once (exit $rc)"
has "$TMP/err" "a FIFO, not a regular file" "FIFO message says it is not a regular file"
printf '[operating]\naxial_load_N = 0x10\n' >"$TMP/hex.ini"
"$ACBB" check "$TMP/hex.ini" >"$TMP/out" 2>"$TMP/err"
code $? 2 "check: a hexadecimal value exits 2"
printf '[operating]\naxial_load_N = 5\033[2J\n' >"$TMP/esc.ini"
"$ACBB" check "$TMP/esc.ini" >"$TMP/out" 2>"$TMP/err"
code $? 2 "check: a control character in a preset exits 2"
! grep -q "$(printf '\033')" "$TMP/err"
t $? "no raw escape character reaches the terminal"

# acbb keys shows each range as the check applies it (open or closed ends).
"$ACBB" keys >"$TMP/keys2.txt" 2>&1
grep -A1 -x 'bearing.ball_diameter_mm = 6.35' "$TMP/keys2.txt" | grep -q '(0, 100\] mm'
t $? "keys: ball diameter shown as (0, 100] mm (0 refused, 100 accepted)"
grep -A1 -x 'bearing.n_balls = 21' "$TMP/keys2.txt" | grep -q '\[3, 64\]'
t $? "keys: n_balls shown as the closed interval [3, 64]"

# acbb edit: the preset changes in place, one line, comments kept.
printf '; my bearing\n[operating]\n; the load I test\naxial_load_N = 1000 ; N\n\ninner_speed_rpm = 15000\n' \
    >"$TMP/mine.ini"
cp "$TMP/mine.ini" "$TMP/mine.orig"
"$ACBB" edit "$TMP/mine.ini" --set operating.axial_load_N=500 >"$TMP/out" 2>"$TMP/err"
code $? 0 "edit exits 0"
[ "$(diff "$TMP/mine.orig" "$TMP/mine.ini" | grep -c '^[<>]')" = 2 ] \
    && grep -q '^; the load I test$' "$TMP/mine.ini" && grep -q '^axial_load_N = 500' "$TMP/mine.ini"
t $? "edit rewrote exactly the one line; comments stay"
"$ACBB" edit "$TMP/mine.ini" --set bearing.ball_diameter_mm=-3 >/dev/null 2>"$TMP/err"
code $? 2 "edit with a bad value exits 2"
grep -q '^axial_load_N = 500' "$TMP/mine.ini"
t $? "and leaves the file as it was"

# The summary's scene line says what the mounting takes: a rigid single
# bearing has no axial force input, a set its preload and the nose loads.
"$ACBB" run presets/runaway-rigid-preload.ini --set thermal.max_time_s=10 >"$TMP/rig.txt" 2>/dev/null
grep -q '^scene        16000 rpm, Fr 0 N,' "$TMP/rig.txt" \
    && grep -q -x 'mounting     rigid preload 1000 N at assembly (axial offset fixed)' "$TMP/rig.txt"
t $? "a rigid single bearing: no Fx on the scene line, the assembly preload on its own"
"$ACBB" run presets/pair-spring-16k.ini --set thermal.max_time_s=10 >"$TMP/pair.txt" 2>/dev/null
grep -q -x 'mounting     DB set, spring preload 300 N at assembly, loads at the nose' "$TMP/pair.txt"
t $? "a DB pair: arrangement, preload kind and value"
"$ACBB" run presets/7008C.ini --set thermal.max_time_s=10 >"$TMP/one.txt" 2>/dev/null
grep -q '^scene        15000 rpm, Fx 1000 N, Fr 0 N,' "$TMP/one.txt" && ! grep -q '^mounting' "$TMP/one.txt"
t $? "one bearing under a force: Fx and Fr, no mounting line"

# A sweep's CSV has the JSONL's doubles, all 17 digits (the README said
# %.10g; issue 28 item 13).
"$ACBB" sweep "$PRESET" --param operating.axial_load_N --values 300 --csv "$TMP/digits.csv" \
    --jsonl "$TMP/digits.jsonl" >/dev/null 2>&1
csv_total=$(awk -F, '/^#/ { next } !c { for (i = 1; i <= NF; i++) if ($i == "losses_W.total") c = i
                                              next } { print $c; exit }' "$TMP/digits.csv")
[ -n "$csv_total" ] && jq -e --argjson v "$csv_total" 'select(.index == 0) | ."losses_W.total" == $v' \
    "$TMP/digits.jsonl" >/dev/null && [ "$(printf %s "$csv_total" | tr -d '.-' | sed 's/^0*//' | wc -c)" -gt 11 ]
t $? "sweep --csv: losses_W.total $csv_total, the JSONL's double to the last digit"

# Progress of the batch commands (issue 28 item 13): study counts its runs,
# sensitivity's count has an ETA (the first run always draws the line).
ACBB_PROGRESS=1 "$ACBB" study "$PRESET" >"$TMP/study.txt" 2>"$TMP/err"
tr '\r' '\n' <"$TMP/err" | grep -q '^study: 48/48 runs, [0-9.]* runs/s$'
t $? "study PRESET shows its progress (study: N/48 runs)"
# ... and its tables fit 80 columns (they were 85), as does the fidelity
# ladder's (84)
"$ACBB" bench accuracy "$PRESET" --knobs mech_tol --repeat 1 >"$TMP/acc.txt" 2>/dev/null
grep -q '^mech_tol=1e-8 ' "$TMP/acc.txt" && grep -q 'total loss W' "$TMP/study.txt" &&
    awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/study.txt" "$TMP/acc.txt"
t $? "study and bench accuracy tables fit 80 columns"
# ... with failed points (a row's mark, the reasons whole and wrapped), the
# reference profile's eight losses in a sweep (one line was 103 columns),
# the preload window's legend (83)
"$ACBB" study presets/combined-load.ini >"$TMP/st2.txt" 2>/dev/null
"$ACBB" sweep presets/combined-load.ini --param operating.radial_load_N --values 300,600 \
    >"$TMP/sw2.txt" 2>/dev/null
"$ACBB" preload-map presets/preload-window.ini --speeds 4000:16000:3 --preloads 50:1500:3 \
    >"$TMP/pm2.txt" 2>/dev/null
grep -q '^\*    50 ' "$TMP/st2.txt" && grep -q 'or mounting.preload = displacement$' "$TMP/st2.txt" &&
    grep -q 'ehl_rolling' "$TMP/sw2.txt" && grep -q '^cells: \. ok' "$TMP/pm2.txt" &&
    awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/st2.txt" "$TMP/sw2.txt" "$TMP/pm2.txt"
t $? "a study with failed points, an eight-loss sweep and the preload window fit 80 columns"
ACBB_PROGRESS=1 "$ACBB" sensitivity "$PRESET" --metric losses_W.total \
    --set fidelity.thermal_mode=steady >/dev/null 2>"$TMP/err"
tr '\r' '\n' <"$TMP/err" | grep -q '^sensitivity: 1/[0-9]* runs, [0-9.]* runs/s, ETA [0-9]* s'
t $? "sensitivity's progress has an ETA"

tap_done
