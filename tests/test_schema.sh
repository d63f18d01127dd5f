#!/bin/sh
# The JSON contract (issue 21 item 10), TAP: `acbb schema` prints the
# schema file; every preset's `acbb run --json`, a run that never started
# and the bad_input document of exit 2 validate against it (schema_check.py:
# python3-jsonschema's Draft 2020-12 validator, issue 28 item 6); the
# schema is strict: a status outside its enum, a converged run without its
# results, a key it does not describe are refused; every metric is
# described; numbers carry 17 significant digits.
# Usage: test_schema.sh PATH/TO/acbb   (cwd = repo root)
set -u
ACBB=${1:?usage: test_schema.sh PATH/TO/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-schema.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
SCHEMA=docs/schema/acbb.schema.json
# Debian's python3 with python3-jsonschema first (dev.sh installs it), then
# whatever python3 is first on PATH.
PY=""
for c in /usr/bin/python3 python3; do
    "$c" -c 'import jsonschema' 2>/dev/null && { PY=$c; break; }
done
if [ -z "$PY" ]; then
    echo "1..0 # SKIP no python3 with jsonschema (apt-get install python3-jsonschema)"
    exit 0
fi
CHECK="$PY $(dirname "$0")/schema_check.py $SCHEMA"

"$ACBB" schema >"$TMP/schema.json"
code $? 0 "acbb schema runs"
cmp -s "$TMP/schema.json" "$SCHEMA"
t $? "and prints docs/schema/acbb.schema.json byte for byte"
$PY -c 'import json, sys, jsonschema
jsonschema.Draft202012Validator.check_schema(json.load(open(sys.argv[1])))' "$SCHEMA"
t $? "the schema is a valid Draft 2020-12 schema"
! grep -q 'MODEL\.md' "$SCHEMA"
t $? "the installed schema cites docs/physics.md, never the unshipped MODEL.md"

mkdir "$TMP/runs"
for p in presets/*.ini; do
    pn=$(basename "$p" .ini)
    "$ACBB" run "$p" --json >"$TMP/runs/$pn.json" 2>/dev/null
done
# one checker process for all (python's start-up, not the check, is the cost)
$CHECK "$TMP"/runs/*.json 2>"$TMP/bad"
t $? "acbb run --json of every preset ($(ls presets/*.ini | wc -l)) conforms to the schema $(head -3 "$TMP/bad" | tr '\n' ' ')"
jq -e '.schema_version == 4' "$TMP/runs/7008C.json" >/dev/null
t $? "the run document says schema_version 4"
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

# every other kind of JSON document (issue 21 item 10): schema_version 4 and
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
"$ACBB" sweep presets/7008C.ini --grid operating.axial_load_N=100,200 --no-stiffness \
    --jsonl "$TMP/ns.jsonl" >/dev/null 2>&1 &&
    head -1 "$TMP/ns.jsonl" >"$TMP/ns_head.json" && tail -n +2 "$TMP/ns.jsonl" >"$TMP/ns_rec.jsonl" &&
    $CHECK --def sweep_header "$TMP/ns_head.json" && $CHECK --def sweep_record --lines "$TMP/ns_rec.jsonl" &&
    jq -e '.acbb_sweep.stiffness == false' "$TMP/ns_head.json" >/dev/null
t $? "sweep --no-stiffness: its header (\"stiffness\": false) and records conform"
"$ACBB" sweep presets/7008C.ini --param operating.axial_load_N --values 100,200 --json \
    >"$TMP/sw.json" 2>/dev/null && $CHECK --def sweep_point --each "$TMP/sw.json"
t $? "sweep --json: each point conforms (sweep_point)"
"$ACBB" sweep presets/7008C.ini --grid operating.axial_load_N=100,200 --metric life.Lnmr_h \
    --jsonl "$TMP/mt.jsonl" --csv "$TMP/mt.csv" >/dev/null 2>&1
head -1 "$TMP/mt.jsonl" >"$TMP/mt_head.json" && tail -n +2 "$TMP/mt.jsonl" >"$TMP/mt_rec.jsonl" &&
    $CHECK --def sweep_header "$TMP/mt_head.json" "$TMP/mt.csv.json" &&
    $CHECK --def sweep_record --lines "$TMP/mt_rec.jsonl"
t $? "sweep --metric: the header (metrics), the CSV's sidecar and the records conform"
"$ACBB" preload-map presets/7008C.ini --speeds 8000:12000:2 --preloads 100:300:2 --max-rise 30 \
    --json >"$TMP/pm.json" 2>/dev/null && $CHECK --def preload_map "$TMP/pm.json"
t $? "preload-map --json conforms (preload_map)"
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

# Strict (issue 28 item 6): each of these used to pass.
# refused DOC JQ-FILTER NAME: DOC changed by the filter fails validation.
refused() {
    jq "$2" "$TMP/runs/$1.json" >"$TMP/changed.json" && ! $CHECK "$TMP/changed.json" 2>/dev/null
    t $? "$3"
}
refused 7008C '.status = "banana"' "the validator rejects status \"banana\""
refused 7008C 'del(.losses_W)' "the validator rejects a converged run without losses_W"
refused 7008C '.life.C0_N_typo = 1' \
    "the validator rejects a key the schema does not describe (life.C0_N_typo)"
jq -e '.branches and .bearings and .set and .life' "$TMP/runs/pair-DB-heated.json" >/dev/null
t $? "pair-DB-heated's document has branches, bearings, set and life"
refused pair-DB-heated '.branches.steady.status = "banana"' \
    "branches are described (a branch's status outside the enum is refused)"
refused pair-DB-heated '.bearings[1].set = 1' "bearings are described (an extra key refused)"
refused pair-DB-heated 'del(.set.preload_N)' "set is described (its keys required)"
# Every metric `acbb metrics` lists has its place in the schema's run.
$PY - "$SCHEMA" "$TMP/met.json" <<'PY' >"$TMP/undescribed" 2>&1
import json, re, sys
run = json.load(open(sys.argv[1]))["$defs"]["run"]
missing = []
for m in json.load(open(sys.argv[2]))["metrics"]:
    node = run
    for part in re.sub(r"\[(i|[0-9]+)\]", "[]", m["path"]).split("."):
        if part.endswith("[]"):
            node = node["properties"][part[:-2]]["items"]
        else:
            node = node.get("properties", {}).get(part)
        if node is None:
            missing.append(m["path"])
            break
print(" ".join(missing))
sys.exit(1 if missing else 0)
PY
t $? "every metric of acbb metrics --json is described in the run schema $(cat "$TMP/undescribed")"
# The other root documents: an ill-posed scene (exit 2), the FFI's refusal
# and a set-up the cancel flag stopped (not_started).
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=0 --set operating.radial_load_N=500 \
    --json >"$TMP/ill.json" 2>/dev/null
code $? 2 "an ill-posed scene exits 2"
$CHECK "$TMP/ill.json"
t $? "its document conforms ($(head -c 60 "$TMP/ill.json"))"
LIB=$(dirname "$ACBB")/libacbb.so
if [ -f "$LIB" ]; then
    $PY - "$LIB" "$TMP" <<'PY'
import ctypes, sys
lib = ctypes.CDLL(sys.argv[1])
f = lib.acbb_run_preset_json_ctl
f.restype = ctypes.c_void_p
f.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t,
              ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_int)]
text = open("presets/7008C.ini", "rb").read()
for name, t, flag in (("cancelled", text, 1), ("nul", b"[operating]\naxial_load_N = 1\0\n", 0)):
    st, c = ctypes.c_int(0), ctypes.c_int(flag)
    p = f(t, len(t), None, 0, ctypes.byref(c), ctypes.byref(st))
    open(f"{sys.argv[2]}/ffi_{name}.json", "wb").write(ctypes.string_at(p))
PY
    jq -e '.status == "cancelled" and .iterations == 0' "$TMP/ffi_cancelled.json" >/dev/null \
        && $CHECK "$TMP/ffi_cancelled.json" "$TMP/ffi_nul.json"
    t $? "the FFI's cancelled set-up (not_started) and its refusal conform"
else
    skip "the FFI's cancelled set-up and refusal conform" "no $LIB"
fi

tap_done
