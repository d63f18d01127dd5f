#!/bin/sh
# One name per quantity and 17 digits in every CSV (issue 28 item 7): the
# `bench accuracy` and `study` CSVs name their columns as `acbb metrics`
# and the scene keys do, in the same units, and print the doubles
# themselves (the run JSON's); the run JSON gives each input once
# (schema 4: scene.keys alone), and a schema-3 document still serves as a
# --baseline. TAP. $1 = the acbb binary; cwd = repository
# root. (The preload map's CSV and JSON: test_life_cli.sh; the sweep's:
# test_sweep_io.sh.)
set -u
ACBB=${1:?usage: test_csv_names.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-csv-names.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
P=presets/7008C.ini

"$ACBB" run $P --json >"$TMP/run.json" 2>/dev/null
"$ACBB" metrics >"$TMP/metrics"

# ---- the run JSON: each input once ----
jq -e '.schema_version == 4 and (.scene | keys == ["keys"])
    and .scene.keys["operating.axial_load_N"] == 1000 and .scene.keys["fidelity.model"] == "quasi-dynamic"' \
    "$TMP/run.json" >/dev/null
t $? "run JSON: schema_version 4, scene holds keys alone (no copies of five inputs beside them)"
# a schema-3 document (the copies beside keys) as the baseline
jq '.schema_version = 3 | .scene += {inner_speed_rpm: 15000, axial_load_N: 1000, radial_load_N: 0,
    thermal_expansion: true, model: "quasi-dynamic"}' "$TMP/run.json" >"$TMP/v3.json"
"$ACBB" run $P --set operating.axial_load_N=500 --baseline "$TMP/v3.json" --json >"$TMP/vs.json" 2>/dev/null
jq -e '[.vs_baseline[] | select(.path | startswith("scene"))] == [{"path": "scene.keys.operating.axial_load_N",
    "baseline": 1000, "now": 500, "change": -500, "change_pct": -50}]' "$TMP/vs.json" >/dev/null
t $? "a schema-3 run document serves as --baseline: the input named once, by its key"

# ---- bench accuracy ----
"$ACBB" bench accuracy $P --knobs contact_grid --repeat 1 --csv "$TMP/acc.csv" >/dev/null 2>&1
code $? 0 "bench accuracy --csv runs"
head -n 1 "$TMP/acc.csv" | grep -q -x -F 'knob,key,value,is_reference,is_default,status,iterations,wall_ms,losses_W.total,dT_outer_K,balls[0].Qi_N,balls[0].alpha_i_deg,balls[0].slide_i_mps,e_loss,e_T,e_Qi,e_alpha,e_slide,work'
t $? "accuracy CSV: results by their acbb metrics paths (alpha in degrees, not alpha_i_rad; slide_i_mps, not slide_i_m_s)"
for m in losses_W.total 'balls\[i\].Qi_N' 'balls\[i\].alpha_i_deg' 'balls\[i\].slide_i_mps'; do
    grep -q "^$m " "$TMP/metrics" || echo "# $m not in acbb metrics"
done | grep -q .
[ $? -ne 0 ]; t $? "  and acbb metrics lists each"
python3 - "$TMP/acc.csv" "$TMP/run.json" <<'PY'
import csv, json, sys
row = [r for r in csv.DictReader(open(sys.argv[1])) if r["is_default"] == "1"][0]
run = json.load(open(sys.argv[2]))
b = run["balls"][0]
want = {"losses_W.total": run["losses_W"]["total"], "balls[0].Qi_N": b["Qi_N"],
        "balls[0].alpha_i_deg": b["alpha_i_deg"], "balls[0].slide_i_mps": b["slide_i_mps"]}
for k, v in want.items():
    assert float(row[k]) == v, (k, row[k], v)
PY
t $? "  the default setting's row holds the run JSON's doubles exactly (17 digits, the same units)"

# ---- study ----
"$ACBB" study $P --csv "$TMP/study.csv" >/dev/null 2>&1
code $? 0 "study --csv runs"
head -n 1 "$TMP/study.csv" | grep -q '^sweep,operating\.inner_speed_rpm,operating\.axial_load_N,te_status,'
t $? "study CSV: the scene keys by their full names (operating.axial_load_N, as sweeps say)"
