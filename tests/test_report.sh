#!/bin/sh
# End-to-end test of `acbb report` (TAP). $1 = path of the acbb binary;
# cwd = repository root. Needs jq. Checks the report's bookkeeping (every
# MODEL.md section 12 item exactly once, counts that add up, JSON that
# agrees with the table), that the sanity item 18 holds, that no nan/inf
# is printed (issue 11), that item 1's
# numbers are the ones `acbb run` gives for the same operating points, the
# Markdown file, and the exit status of bad input.
set -u

ACBB=${1:?usage: test_report.sh path/to/acbb}
PRESET=presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-report.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM

. "$(dirname "$0")/tap.sh"

# ---- the text report ----
"$ACBB" report "$PRESET" --md "$TMP/SEED.md" >"$TMP/out.txt" 2>"$TMP/err"
code $? 0 "report $PRESET runs"

# Item lines: "%3d  VERDICT ..." (checks and conclusions are formatted otherwise).
grep -E '^ {0,2}[0-9]{1,2}  (HELD|NOT HELD|NOT EVALUATED) ' "$TMP/out.txt" >"$TMP/items.txt"
awk '{print $1}' "$TMP/items.txt" >"$TMP/nums.txt"
seq 1 18 >"$TMP/want.txt"
cmp -s "$TMP/nums.txt" "$TMP/want.txt"
t $? "items 1..18 each appear exactly once, in order, with a verdict"
[ "$(wc -l <"$TMP/items.txt")" -eq 18 ]
t $? "exactly 18 item lines"

held=$(grep -c -E '^ {0,2}[0-9]{1,2}  HELD ' "$TMP/items.txt")
nheld=$(grep -c -E '^ {0,2}[0-9]{1,2}  NOT HELD ' "$TMP/items.txt")
ne=$(grep -c -E '^ {0,2}[0-9]{1,2}  NOT EVALUATED ' "$TMP/items.txt")
summary=$(grep -E '^[0-9]+ held, [0-9]+ not held, [0-9]+ not evaluated$' "$TMP/out.txt")
[ -n "$summary" ]
t $? "summary line present: $summary"
set -- $(echo "$summary" | sed -E 's/^([0-9]+) held, ([0-9]+) not held, ([0-9]+) not evaluated$/\1 \2 \3/')
[ "${1:-x}" = "$held" ] && [ "${2:-x}" = "$nheld" ] && [ "${3:-x}" = "$ne" ]
t $? "summary counts match the item verdicts ($held/$nheld/$ne)"
[ $((${1:-0} + ${2:-0} + ${3:-0})) -eq 18 ]
t $? "summary counts add up to 18"

grep -q -E '^ 18  HELD ' "$TMP/items.txt"
t $? "item 18 (sanity: zero speed, energy balance, closed form, losses >= 0, BE) is HELD"

awk 'length > 80 { bad = 1 } END { exit bad }' "$TMP/out.txt"
t $? "the text report fits 80 columns"

# ---- Markdown ----
[ -s "$TMP/SEED.md" ] && grep -q '^# Seed report' "$TMP/SEED.md"
t $? "--md writes the Markdown report"
grep -q -F "**$held held, $nheld not held, $ne not evaluated** (of 18)." "$TMP/SEED.md"
t $? "Markdown summary equals the text summary"
[ "$(grep -c -E '^\| [0-9]+ \| (HELD|NOT HELD|NOT EVALUATED) \|' "$TMP/SEED.md")" -eq 18 ]
t $? "Markdown table has 18 item rows"
[ -z "$(find "$TMP" -name 'SEED.md.tmp*')" ]
t $? "no temporary Markdown file left behind"

# ---- JSON ----
"$ACBB" report "$PRESET" --json >"$TMP/out.json" 2>"$TMP/err"
code $? 0 "report --json runs"
# --jobs changes the workers, never the verdicts or numbers.
"$ACBB" report "$PRESET" --json --jobs 1 >"$TMP/out1.json" 2>"$TMP/err"
code $? 0 "report --json --jobs 1 runs"
jq -S 'del(.. | .wall_ms?)' "$TMP/out.json" >"$TMP/o2.json"
jq -S 'del(.. | .wall_ms?)' "$TMP/out1.json" >"$TMP/o1.json"
cmp -s "$TMP/o1.json" "$TMP/o2.json"
t $? "report --jobs 1 gives the JSON of the default job count"
jq -e 'type == "array" and length == 18 and ([.[].item] == [range(1; 19)])' "$TMP/out.json" >/dev/null 2>&1
t $? "JSON parses: an array of items 1..18"
jq -e 'all(.[]; (.statement | length) > 0 and (.verdict == "HELD" or .verdict == "NOT HELD" or .verdict == "NOT EVALUATED") and (.evidence.checks | length) > 0)' \
    "$TMP/out.json" >/dev/null 2>&1
t $? "every JSON item has a statement, a verdict and checks"
jq -r '.[] | "\(.item) \(.verdict)"' "$TMP/out.json" >"$TMP/jv.txt"
sed -E 's/^ *([0-9]+)  (HELD|NOT HELD|NOT EVALUATED) .*/\1 \2/' "$TMP/items.txt" >"$TMP/tv.txt"
cmp -s "$TMP/jv.txt" "$TMP/tv.txt"
t $? "JSON verdicts agree with the text verdicts"

# ---- item 1's numbers are `acbb run`'s ----
for F in 200 1000; do
    for M in on off; do
        if [ "$M" = on ]; then tag=TE; else tag=WTE; fi
        run=$("$ACBB" run "$PRESET" --set operating.inner_speed_rpm=15000 \
              --set operating.axial_load_N=$F --set effects.thermal_expansion=$M --json |
              jq -r '.losses_W.total')
        rep=$(jq -r ".[0].evidence.values.P_T_${tag}_W_${F}N" "$TMP/out.json")
        a=$(printf '%.4g' "$run" 2>/dev/null)
        b=$(printf '%.4g' "$rep" 2>/dev/null)
        [ -n "$a" ] && [ "$a" = "$b" ]
        t $? "item 1 P_T at 15000 rpm, $F N, $tag: report $b W = acbb run $a W"
    done
done

# ---- issue 25 item 6: check 6a's "room temperature" is the WTE state ----
# (MODEL.md 12), so its count is the loads where the WTE angles exceed the
# final TE ones, recomputed here from the item's own values.
want=$(jq -r '.[5].evidence.values as $v | [50,100,150,200,400,600,800,1000] |
    map(select($v["alpha_i_WTE_deg_\(.)N"] > $v["alpha_i_TE_deg_\(.)N"] and
               $v["alpha_o_WTE_deg_\(.)N"] > $v["alpha_o_TE_deg_\(.)N"])) | length' "$TMP/out.json")
jq -r '.[5].evidence.checks[] | select(.id == "6a") | .text' "$TMP/out.json" >"$TMP/6a.txt"
grep -q "^alpha_i, alpha_o deg, room temperature (WTE) -> final (TE):.*both fall at $want of 8\$" \
    "$TMP/6a.txt"
t $? "6a: room temperature is the WTE state; both angles fall at $want of 8 (from the values)"
# ---- and 16c's tail: the numbers shown, the verdict from the stated 2 % ----
jq -r '.[15].evidence.checks[] | select(.id == "16c") | "\(.verdict)\t\(.text)"' "$TMP/out.json" \
    >"$TMP/16c.txt"
awk -F'\t' '{
    v = $1; s = $2; sub(/^.*TE\/WTE: /, "", s); sub(/;.*$/, "", s); n = split(s, e, ", ")
    for (m = 1; m <= 2; m++) {
        pk = 1; for (k = 1; k <= n; k++) { split(e[k], f, " "); split(f[3], x, "/"); y[k] = x[m]
                                          if (y[k] > y[pk]) pk = k }
        lo = pk; for (k = pk; k <= n; k++) if (y[k] < y[lo]) lo = k
        tail = 0; for (k = lo; k <= n; k++) if (y[k] - y[lo] > tail) tail = y[k] - y[lo]
        pct[m] = 100 * tail / (y[pk] - y[lo]); okm[m] = pk > 1 && lo > pk && pct[m] <= 2
        for (k = 2; k <= pk; k++) okm[m] = okm[m] && y[k] > y[k - 1]
        for (k = pk + 1; k <= lo; k++) okm[m] = okm[m] && y[k] < y[k - 1]
    }
    if (!match($2, /; TE peak [^;]* = [0-9.]+ % of the fall/)) exit 1
    te = substr($2, RSTART, RLENGTH); sub(/ % of the fall$/, "", te); sub(/^.* = /, "", te)
    if (!match($2, /WTE peak [^;]* = [0-9.]+ % of the fall/)) exit 1
    wt = substr($2, RSTART, RLENGTH); sub(/ % of the fall$/, "", wt); sub(/^.* = /, "", wt)
    d1 = te - pct[1]; d2 = wt - pct[2]
    shown = d1 < 0.05 && d1 > -0.05 && d2 < 0.05 && d2 > -0.05
    want = (okm[1] && okm[2]) ? "HELD" : "NOT HELD"
    printf "# 16c tails TE %.2f %%, WTE %.2f %% of the fall; shown %s, %s; verdict %s\n",
        pct[1], pct[2], te, wt, v
    exit !(shown && v == want && index($2, "within 2 % of the fall") > 0)
}' "$TMP/16c.txt"
t $? "16c: the tail after the low is shown as a share of the fall, the verdict follows the stated 2 %"

# ---- issue 11: no NaN/Inf reaches the report (axial load 0) ----
"$ACBB" report "$PRESET" --set operating.axial_load_N=0 >"$TMP/zero.txt" 2>"$TMP/err"
code $? 0 "report with axial load 0 runs"
# (item 18's statement says "dt -> inf": words, not a number)
! sed 's/-> inf / /g' "$TMP/zero.txt" | grep -q -i -w -E -- '-?(nan|inf)'
t $? "axial load 0: the text report prints no nan/inf"
"$ACBB" report "$PRESET" --set operating.axial_load_N=0 --json >"$TMP/zero.json" 2>"$TMP/err"
jq -e '[.. | strings | gsub("-> inf "; " ") | select(test("(^|[^a-z_])-?(nan|inf)([^a-z_]|$)"))] | length == 0' \
    "$TMP/zero.json" >/dev/null 2>&1
t $? "axial load 0: no nan/inf in any JSON text"

# ---- --sensitivity (robustness) on one input: surroundings.shaft_bore ----
# (the full run over all 24 inputs is in the slow suite: test_report_sens.sh)
"$ACBB" report "$PRESET" --sensitivity --inputs surroundings.shaft_bore >"$TMP/sens.txt" 2>"$TMP/err"
code $? 0 "report --sensitivity --inputs surroundings.shaft_bore runs"
[ ! -e surroundings.shaft_bore ] && [ ! -e "$TMP/surroundings.shaft_bore" ]
t $? "--inputs writes no file (its value is not a Markdown path)"
sed -n '/^Robustness (--sensitivity/,/^The TE - WTE differences/p' "$TMP/sens.txt" |
    grep -E '^ {0,2}[0-9]{1,2}  (HELD|NOT HELD|NOT EVALUATED); ' | awk '{print $1}' >"$TMP/rnums.txt"
cmp -s "$TMP/rnums.txt" "$TMP/want.txt"
t $? "the robustness block lists items 1..18 once each, in order, with a verdict"
grep -q -E '^ 18  HELD; model-independent sanity item, not varied' "$TMP/sens.txt"
t $? "item 18 is not varied"
tr '\n' ' ' <"$TMP/sens.txt" | tr -s ' ' |
    grep -q -E 'one at a time: 1 inputs, 1 ends \(1 at the scene.s value\), 52 runs'
t $? "one input, one end (fixed is the scene's own), 52 runs (every point but the zero-speed one)"
tr '\n' ' ' <"$TMP/sens.txt" | tr -s ' ' | grep -q -F 'surroundings.shaft_bore = convective (1b ok)'
t $? "item 1: a convective shaft bore turns check 1b (TE > WTE at the large loads)"
awk 'length > 80 { bad = 1 } END { exit bad }' "$TMP/sens.txt"
t $? "the robustness text fits 80 columns"

"$ACBB" report "$PRESET" --sensitivity --inputs surroundings.shaft_bore --json >"$TMP/sens.json" 2>"$TMP/err"
code $? 0 "report --sensitivity --json runs"
jq -e 'all(.[]; .robustness.inputs == 1 and .robustness.ends == 1 and (.robustness.varied == (.item != 18)))' \
    "$TMP/sens.json" >/dev/null 2>&1
t $? "JSON: every item has its robustness (1 input, 1 end), item 18 not varied"
jq -e '.[4].robustness.changes | map(select(.key == "surroundings.shaft_bore" and .value == "convective")) | .[0].checks | map(.id) | (index("5a") != null and index("5d") != null)' \
    "$TMP/sens.json" >/dev/null 2>&1
t $? "JSON: item 5's checks 5a (contact loads rise) and 5d (final > WTE at large loads) change with a convective bore"
# The known number: P_T(TE) - P_T(WTE) at 15000 rpm, 1000 N with a convective bore, as `acbb run` gives it.
for M in on off; do
    "$ACBB" run "$PRESET" --set operating.inner_speed_rpm=15000 --set operating.axial_load_N=1000 \
        --set surroundings.shaft_bore=convective --set effects.thermal_expansion=$M --json 2>/dev/null |
        jq -r '.losses_W.total' >"$TMP/pt_$M"
done
want=$(awk -v a="$(cat "$TMP/pt_on")" -v b="$(cat "$TMP/pt_off")" 'BEGIN { printf "%.4g", a - b }')
got=$(jq -r '.[0].robustness.conditions[0].turned_by[] | select(.key == "surroundings.shaft_bore") | .at' "$TMP/sens.json")
got=$(printf '%.4g' "$got" 2>/dev/null)
[ -n "$want" ] && [ "$want" = "$got" ]
t $? "item 1, P_T(TE) - P_T(WTE) at 1000 N with a convective bore: report $got W = acbb run $want W"
"$ACBB" report "$PRESET" --inputs materials.ball_E_GPa >/dev/null 2>"$TMP/err"
code $? 2 "--inputs with a key that has no plausible range exits 2"
grep -q 'materials.ball_E_GPa is not an uncertain input' "$TMP/err"
t $? "... and says why"

# ---- contact heat models on the runaway case (issue 25 item 3) ----
# Each row is computed: it equals `acbb run` of presets/runaway-rigid-preload.ini
# (the 7008C case the section derives) under that model and multiplier.
jq -e '.[8].contact_heat.runs | length == 8 and ([.[].contact_model] | unique == ["moving", "stationary"])' \
    "$TMP/out.json" >/dev/null 2>&1
t $? "JSON: item 9 carries contact_heat with 8 runs (2 models x 4 multipliers)"
jq -e '[.[] | select(has("contact_heat"))] | length == 1' "$TMP/out.json" >/dev/null 2>&1
t $? "JSON: only item 9 carries it"
bad=0
for i in 0 1 2 3 4 5 6 7; do
    row=$(jq -r ".[8].contact_heat.runs[$i] | \"\(.contact_model) \(.contact_multiplier) \(.status) \(.time_s) \(.T_ball_C)\"" "$TMP/out.json")
    set -- $row
    run=$("$ACBB" run presets/runaway-rigid-preload.ini --set thermal.contact_model="$1" \
          --set thermal.contact_multiplier="$2" --json 2>/dev/null |
          jq -r '"\(.status) \(.time_s) \(.temperature_C.ball)"')
    [ "$3 $4 $5" = "$run" ] || { bad=1; echo "# $1 c_mv $2: report '$3 $4 $5', run '$run'"; }
done
[ "$bad" -eq 0 ]
t $? "every row equals acbb run presets/runaway-rigid-preload.ini under its model and c_mv"
st=$(jq -r '[.[8].contact_heat.runs[] | select(.contact_model == "stationary") | .status] | join(" ")' "$TMP/out.json")
[ "$st" = "converged converged runaway runaway" ]
t $? "stationary spots: the runaway case converges at c_mv 0.25 and 0.5, runs away at 1 and 2 ($st)"
mv=$(jq -r '[.[8].contact_heat.runs[] | select(.contact_model == "moving") | .status] | join(" ")' "$TMP/out.json")
[ "$mv" = "converged converged converged converged" ]
t $? "moving source: converged at every c_mv ($mv)"
grep -q -E '^stationary  converged at c_mv 0.25, 0.5; runaway at c_mv 1, 2$' "$TMP/out.txt" &&
    grep -q -E '^moving      converged at c_mv 0.25, 0.5, 1, 2$' "$TMP/out.txt"
t $? "text: each model's branches by c_mv, as the JSON says"
[ "$(sed -n '/^Contact heat paths/,$p' "$TMP/out.txt" | grep -c -E '^(stationary|moving) +[0-9.]+  (converged|runaway) ')" -eq 8 ]
t $? "text: 8 rows in the contact heat section"
[ "$(sed -n '/^## Contact heat models/,/^## Evidence/p' "$TMP/SEED.md" | grep -c -E '^\| (stationary|moving) \|')" -eq 8 ]
t $? "Markdown: the contact heat table has 8 rows"

# ---- bad input ----
"$ACBB" report "$PRESET" --set operating.axial_load_N=abc >/dev/null 2>"$TMP/err"
code $? 2 "bad --set value exits 2"
grep -q 'operating.axial_load_N' "$TMP/err"
t $? "the message names the bad key"
"$ACBB" report "$PRESET" --set nosuch.key=1 >/dev/null 2>"$TMP/err"
code $? 2 "unknown --set key exits 2"
"$ACBB" report >/dev/null 2>"$TMP/err"
code $? 2 "missing preset exits 2"
"$ACBB" report "$TMP/none.ini" >/dev/null 2>"$TMP/err"
code $? 2 "missing preset file exits 2"
"$ACBB" report "$PRESET" --md "$TMP/no/such/dir/x.md" >/dev/null 2>"$TMP/err"
code $? 2 "unwritable --md path exits 2"

tap_done
