#!/bin/sh
# The JSON contract (issue 21 item 10), TAP: `acbb schema` prints the
# schema file; every preset's `acbb run --json`, a run that never started
# and the bad_input document of exit 2 validate against it (schema_check.py:
# the subset the schema uses); the checker itself rejects a broken
# document; numbers carry 17 significant digits.
# Usage: test_schema.sh PATH/TO/acbb   (cwd = repo root)
set -u
ACBB=${1:?usage: test_schema.sh PATH/TO/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-schema.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
SCHEMA=docs/schema/acbb.schema.json
CHECK="python3 $(dirname "$0")/schema_check.py $SCHEMA"

"$ACBB" schema >"$TMP/schema.json"
code $? 0 "acbb schema runs"
cmp -s "$TMP/schema.json" "$SCHEMA"
t $? "and prints docs/schema/acbb.schema.json byte for byte"
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$SCHEMA"
t $? "the schema is JSON"

mkdir "$TMP/runs"
for p in presets/*.ini; do
    pn=$(basename "$p" .ini)
    "$ACBB" run "$p" --json >"$TMP/runs/$pn.json" 2>/dev/null
done
# one checker process for all (python's start-up, not the check, is the cost)
$CHECK "$TMP"/runs/*.json 2>"$TMP/bad"
t $? "acbb run --json of every preset ($(ls presets/*.ini | wc -l)) conforms to the schema $(head -3 "$TMP/bad" | tr '\n' ' ')"
jq -e '.schema_version == 3' "$TMP/runs/7008C.json" >/dev/null
t $? "the run document says schema_version 3"
# 17 significant digits: the printed number is the double itself
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); v=d["time_s"]; assert repr(v) == repr(float("%.17g" % v)) and len(json.dumps(d["losses_W"]["total"]).replace(".","").lstrip("0")) > 11' "$TMP/runs/7008C.json"
t $? "numbers are printed with full precision (more than 10 digits)"

# exit 2 with --json: a bad_input document on stdout, the message on stderr
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=-5 --json >"$TMP/bad.json" 2>"$TMP/err"
code $? 2 "a bad --set value exits 2"
jq -e '.status == "bad_input" and (.message | test("must be >= 0 N"))' "$TMP/bad.json" >/dev/null
t $? "with --json it prints {status: bad_input, message} ($(cat "$TMP/bad.json"))"
$CHECK "$TMP/bad.json"
t $? "the bad_input document conforms to the schema"
grep -q "must be >= 0 N" "$TMP/err"
t $? "and the message still goes to stderr"
"$ACBB" sweep presets/7008C.ini --bogus --json >"$TMP/bad2.json" 2>/dev/null
code $? 2 "an unknown option of sweep exits 2"
jq -e '.status == "bad_input" and (.message | test("unknown option --bogus"))' "$TMP/bad2.json" >/dev/null
t $? "and prints the bad_input document too"
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=-5 >"$TMP/plain" 2>/dev/null
[ ! -s "$TMP/plain" ]
t $? "without --json nothing goes to stdout"

# --baseline: a temperature's change in % of its rise above ambient, as the
# TUI's Run screen shows it (issue 21 item 7); hand calculation from the two runs
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=500 --baseline "$TMP/runs/7008C.json" --json \
    >"$TMP/vs.json" 2>/dev/null
jq -e --slurpfile b "$TMP/runs/7008C.json" '
    (.vs_baseline[] | select(.path == "temperature_C.outer_ring")) as $r
    | ($b[0].temperature_C.outer_ring - $b[0].scene.keys["operating.ambient_C"]) as $rise
    | ($r.change_pct - 100 * ($r.now - $r.baseline) / $rise) | fabs < 1e-9' "$TMP/vs.json" >/dev/null
t $? "--baseline: temperature change_pct is of the rise above ambient ($(jq '.vs_baseline[] | select(.path == "temperature_C.outer_ring") | .change_pct' "$TMP/vs.json") %)"

# every other kind of JSON document (issue 21 item 10): schema_version 3 and
# the schema's $defs entry for its kind
"$ACBB" sweep presets/7008C.ini --grid operating.axial_load_N=100,200 --jsonl "$TMP/s.jsonl" \
    >/dev/null 2>&1
code $? 0 "sweep --jsonl runs"
head -1 "$TMP/s.jsonl" >"$TMP/s_head.json"
tail -n +2 "$TMP/s.jsonl" >"$TMP/s_rec.jsonl"
$CHECK --def sweep_header "$TMP/s_head.json" && [ "$(wc -l <"$TMP/s_rec.jsonl")" -eq 2 ] &&
    $CHECK --def sweep_record --lines "$TMP/s_rec.jsonl"
t $? "sweep --jsonl: the header and both records conform (sweep_header, sweep_record)"
"$ACBB" merge "$TMP/m.jsonl" "$TMP/s.jsonl" 2>/dev/null &&
    head -1 "$TMP/m.jsonl" >"$TMP/m_head.json" && tail -n +2 "$TMP/m.jsonl" >"$TMP/m_rec.jsonl" &&
    $CHECK --def sweep_header "$TMP/m_head.json" && $CHECK --def sweep_record --lines "$TMP/m_rec.jsonl"
t $? "merge: the merged file's header and records conform"
"$ACBB" sweep presets/7008C.ini --param operating.axial_load_N --values 100,200 --json \
    >"$TMP/sw.json" 2>/dev/null && $CHECK --def sweep_point --each "$TMP/sw.json"
t $? "sweep --json: each point conforms (sweep_point)"
"$ACBB" report presets/7008C.ini --json >"$TMP/rep.json" 2>/dev/null &&
    $CHECK --def report_item --each "$TMP/rep.json"
t $? "report --json: each item conforms (report_item)"
"$ACBB" sensitivity presets/7008C.ini --metric losses_W.total --json >"$TMP/sens.json" \
    2>/dev/null && $CHECK --def sensitivity "$TMP/sens.json"
t $? "sensitivity --json conforms (sensitivity)"
"$ACBB" metrics --json >"$TMP/met.json" && $CHECK --def metrics "$TMP/met.json" &&
    jq -e '.metrics[] | select(.path == "temperature_C.outer_ring") | .unit == "C"' \
        "$TMP/met.json" >/dev/null
t $? "metrics --json conforms (metrics) and lists temperature_C.outer_ring in C"

# one name per quantity (schema 3): a sweep record, the sweep --json point
# and the metrics listing name each value by the run document's path, with
# the same double; old column names still name it where a user passes one
jq -e '.metrics | all(.[]; .column == (.path | sub("\\[i\\]"; "[0]")))' "$TMP/met.json" >/dev/null
t $? "metrics --json: every column name is the run path (ball 0)"
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=200 --set fidelity.thermal_mode=steady \
    --json >"$TMP/r200.json" 2>/dev/null
jq -s -e --slurpfile r "$TMP/r200.json" 'map(select(.index == 1))[0] |
    ."temperature_C.outer_ring" == $r[0].temperature_C.outer_ring and
    ."ring.stiffness_axial_N_per_um" == $r[0].ring.stiffness_axial_N_per_um and
    ."balls[0].Qi_N" == $r[0].balls[0].Qi_N' "$TMP/s_rec.jsonl" >/dev/null
t $? "a sweep record's values equal the run's, under the run's names, to the last digit ($(jq -c '[.temperature_C.outer_ring, .iterations]' "$TMP/r200.json") $(jq -c 'select(.index == 1) | [."temperature_C.outer_ring", .iterations]' "$TMP/s_rec.jsonl"))"
jq -e --slurpfile r "$TMP/r200.json" '.[1] | ."losses_W.total" == $r[0].losses_W.total and
    (has("P_total_W") | not)' "$TMP/sw.json" >/dev/null
t $? "sweep --json: losses_W.total, no P_total_W"
"$ACBB" sensitivity presets/7008C.ini --metric T_outer_ring_C --json 2>/dev/null |
    jq -e '.metric == "temperature_C.outer_ring"' >/dev/null
t $? "an old name (--metric T_outer_ring_C) is an alias of temperature_C.outer_ring"
"$ACBB" sensitivity presets/7008C.ini --metric stiffness_axial_N_um --json 2>/dev/null |
    jq -e '.metric == "ring.stiffness_axial_N_per_um"' >/dev/null
t $? "... and stiffness_axial_N_um of ring.stiffness_axial_N_per_um"

jq -e 'del(.schema_version)' "$TMP/sens.json" >"$TMP/broken3.json"
! $CHECK --def sensitivity "$TMP/broken3.json" 2>/dev/null
t $? "the checker rejects a sensitivity document without schema_version"

# the checker can fail: a document without status, a string for a number
jq 'del(.status)' "$TMP/runs/7008C.json" >"$TMP/broken1.json"
! $CHECK "$TMP/broken1.json" 2>/dev/null
t $? "the checker rejects a document without status"
jq '.losses_W.total = "54"' "$TMP/runs/7008C.json" >"$TMP/broken2.json"
! $CHECK "$TMP/broken2.json" 2>/dev/null
t $? "the checker rejects a string where a number belongs"

tap_done
