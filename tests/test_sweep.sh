#!/bin/sh
# N-dimensional sweeps (TAP): shards merged equal the one-machine sweep
# byte for byte; an interrupted sweep resumed equals an uninterrupted one;
# a failed point is recorded and the sweep goes on. $1 = the acbb binary;
# cwd = repository root. Needs jq. Quasi-static points take milliseconds.
set -u

ACBB=${1:?usage: test_sweep.sh path/to/acbb}
PRESET=presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-sweep.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
XDG_CONFIG_HOME="$TMP/xdg"
export XDG_CONFIG_HOME

. "$(dirname "$0")/tap.sh"

# 2 x 2 x 2 = 8 points; the index is row-major, the first --grid slowest.
GRID="--set fidelity.model=quasi-static --grid operating.axial_load_N=200,800
 --grid operating.inner_speed_rpm=4000:12000:2 --grid effects.thermal_expansion=on,off"

# shellcheck disable=SC2086
sweep() { "$ACBB" sweep "$PRESET" $GRID "$@" 2>>"$TMP/err"; }

# ---- one machine ----
sweep --jsonl "$TMP/one.jsonl" --csv "$TMP/one.csv" --jobs 2
code $? 0 "2x2x2 sweep exits 0"
[ "$(wc -l <"$TMP/one.jsonl")" -eq 9 ] && head -1 "$TMP/one.jsonl" | jq -e '.acbb_sweep.format == 4' >/dev/null 2>&1
t $? "a header line, then one JSON line per point"
jq -s -e '.[1:] | map(.index) | sort == [0,1,2,3,4,5,6,7]' "$TMP/one.jsonl" >/dev/null 2>&1
t $? "every index 0..7 once"
jq -s -e 'map(select(.index == 5))[0].grid == {"operating.axial_load_N": 800,
    "operating.inner_speed_rpm": 4000, "effects.thermal_expansion": "off"}' \
    "$TMP/one.jsonl" >/dev/null 2>&1
t $? "point 5 = (800 N, 4000 rpm, off): row-major, last --grid fastest"
jq -s -e 'map(select(.index == 2))[0].grid["operating.inner_speed_rpm"] == 12000' \
    "$TMP/one.jsonl" >/dev/null 2>&1
t $? "lo:hi:2 gives both ends (12000 rpm at index 2)"
jq -s -e 'def abs: if . < 0 then -. else . end; .[1:] | all(.[]; .status == "converged" and .wall_ms >= 0 and
    ((."losses_W.shear" + ."losses_W.slip" + ."losses_W.spin" + ."losses_W.rolling"
      + ."losses_W.drag" + ."losses_W.cage" - ."losses_W.total")
     | abs) <= 1e-9 * ."losses_W.total")' "$TMP/one.jsonl" >/dev/null 2>&1
t $? "every point converged; the loss columns sum to losses_W.total"
[ "$(wc -l <"$TMP/one.csv")" -eq 9 ] && sed -n 1p "$TMP/one.csv" | grep -q '^index,fingerprint,operating.axial_load_N,operating.inner_speed_rpm,effects.thermal_expansion,status,.*,message,wall_ms$'
t $? "CSV: the column header first (grid keys, ..., wall_ms) + 8 rows (issue 28 item 8)"

# The same point alone, through acbb run: the sweep changes nothing else.
# A sweep point is the steady solve (include/acbb/tools/sweep.h), so the run
# says fidelity.thermal_mode=steady; --transient runs the scene's transient.
point6() {
    "$ACBB" run "$PRESET" --set fidelity.model=quasi-static --set operating.axial_load_N=800 \
        --set operating.inner_speed_rpm=12000 --set effects.thermal_expansion=on --json "$@" \
        >"$TMP/run.json" 2>>"$TMP/err"
}
# (both print 17 significant digits from the one output table: equal
# exactly, under the same name; the same steps)
same6() {
    jq -s -e --slurpfile r "$TMP/run.json" 'map(select(.index == 6))[0] |
        ."losses_W.total" == $r[0].losses_W.total and
        ."temperature_C.outer_ring" == $r[0].temperature_C.outer_ring and
        ."ring.stiffness_axial_N_per_um" == $r[0].ring.stiffness_axial_N_per_um and
        .iterations == $r[0].iterations' "$1" >/dev/null 2>&1
}
point6 --set fidelity.thermal_mode=steady
same6 "$TMP/one.jsonl"
t $? "point 6 equals acbb run with the same --set edits and thermal_mode=steady"
sweep --jsonl "$TMP/tr.jsonl" --jobs 2 --transient
point6
same6 "$TMP/tr.jsonl"
t $? "with --transient point 6 equals the plain acbb run (the transient)"

# Where the two differ: the steady solve finds a steady branch the run from
# ambient never reaches (include/acbb/batch.h); --transient catches it.
RUNAWAY=presets/runaway-rigid-preload.ini
"$ACBB" sweep "$RUNAWAY" --grid operating.axial_load_N=1000 --jsonl "$TMP/ra.jsonl" 2>>"$TMP/err"
"$ACBB" sweep "$RUNAWAY" --grid operating.axial_load_N=1000 --jsonl "$TMP/rt.jsonl" --transient \
    2>>"$TMP/err"
jq -e '.status == "converged"' "$TMP/ra.jsonl" >/dev/null 2>&1 &&
    jq -e '.status == "runaway"' "$TMP/rt.jsonl" >/dev/null 2>&1
t $? "runaway preset: the steady solve converges, --transient ends it as runaway"

# The CPUs the process may use: under taskset -c 0 the sweep starts no
# thread (one worker, the main thread); with two CPUs and --jobs 2, one.
if command -v strace >/dev/null 2>&1 && command -v taskset >/dev/null 2>&1 &&
   strace -f -qq -o /dev/null true 2>/dev/null && [ "$(nproc)" -ge 2 ]; then
    clones() {
        strace -f -qq -e trace=clone,clone3 -o "$TMP/strace" taskset -c "$1" "$ACBB" sweep \
            "$PRESET" --grid operating.axial_load_N=200,400,600,800 $2 \
            --jsonl "$TMP/aff$1.jsonl" 2>>"$TMP/err"
        grep -c CLONE_THREAD "$TMP/strace"
    }
    [ "$(clones 0 '')" -eq 0 ]
    t $? "taskset -c 0: one worker, no thread started"
    [ "$(clones 0,1 '--jobs 2')" -eq 1 ]
    t $? "two CPUs, --jobs 2: one thread besides the main one"
else
    skip "strace, taskset or two CPUs missing: the worker count under taskset is not observed"
    skip "strace, taskset or two CPUs missing"
fi

# ---- shards ----
"$ACBB" merge "$TMP/canon.jsonl" "$TMP/one.jsonl" 2>>"$TMP/err"
code $? 0 "merge of one file exits 0"
! grep -q wall_ms "$TMP/canon.jsonl"
t $? "the canonical form has no wall_ms"
for k in 1 2 3; do
    sweep --shard $k/3 --jsonl "$TMP/s$k.jsonl" --csv "$TMP/s$k.csv" --jobs 1
done
[ "$(cat "$TMP"/s?.jsonl | wc -l)" -eq 11 ] && [ "$(wc -l <"$TMP/s2.jsonl")" -eq 4 ] \
    && jq -s -e '.[1:] | map(.index) | sort == [1,4,7]' "$TMP/s2.jsonl" >/dev/null 2>&1
t $? "shards 1/3..3/3 split the 8 points; shard 2 = indices 1, 4, 7"
"$ACBB" merge "$TMP/merged.jsonl" "$TMP/s3.jsonl" "$TMP/s1.jsonl" "$TMP/s2.jsonl" 2>>"$TMP/err"
cmp -s "$TMP/merged.jsonl" "$TMP/canon.jsonl"
t $? "JSONL: merged shards == one-machine canonical output, byte for byte"
"$ACBB" merge "$TMP/canon.csv" "$TMP/one.csv" 2>>"$TMP/err"
"$ACBB" merge "$TMP/merged.csv" "$TMP/s2.csv" "$TMP/s3.csv" "$TMP/s1.csv" 2>>"$TMP/err"
cmp -s "$TMP/merged.csv" "$TMP/canon.csv" && [ "$(wc -l <"$TMP/canon.csv")" -eq 9 ]
t $? "CSV: merged shards == one-machine canonical output, byte for byte"
"$ACBB" merge "$TMP/bad" "$TMP/s1.jsonl" "$TMP/s1.csv" 2>"$TMP/err"
code $? 2 "merge refuses JSONL mixed with CSV"

# ---- interrupt and resume ----
sweep --jsonl "$TMP/part.jsonl" --csv "$TMP/part.csv" --max-points 3 --jobs 2
[ "$(wc -l <"$TMP/part.jsonl")" -eq 4 ]
t $? "--max-points 3 stops after 3 points"
# A record cut in the middle (killed while writing) is dropped and re-run;
# both files end with the same point (written in the same hand-off).
for f in part.jsonl part.csv; do
    head -c -40 "$TMP/$f" >"$TMP/cut" && cat "$TMP/cut" >"$TMP/$f"
done
sweep --jsonl "$TMP/part.jsonl" --csv "$TMP/part.csv" --jobs 2
code $? 0 "the resumed sweep exits 0"
[ "$(wc -l <"$TMP/part.jsonl")" -eq 9 ] && [ "$(wc -l <"$TMP/part.csv")" -eq 9 ]
t $? "resumed: 8 records, none twice (the cut one re-run)"
"$ACBB" merge "$TMP/res.jsonl" "$TMP/part.jsonl" 2>>"$TMP/err"
cmp -s "$TMP/res.jsonl" "$TMP/canon.jsonl"
t $? "resumed JSONL == uninterrupted, canonical form"
"$ACBB" merge "$TMP/res.csv" "$TMP/part.csv" 2>>"$TMP/err"
cmp -s "$TMP/res.csv" "$TMP/canon.csv"
t $? "resumed CSV == uninterrupted, canonical form"
cp "$TMP/one.jsonl" "$TMP/again.jsonl"
sweep --jsonl "$TMP/again.jsonl"
code $? 0 "re-running a finished sweep exits 0"
cmp -s "$TMP/again.jsonl" "$TMP/one.jsonl"
t $? "... and runs nothing (file unchanged)"
"$ACBB" sweep "$PRESET" --grid operating.axial_load_N=1,2 --jsonl "$TMP/one.jsonl" \
    >"$TMP/out" 2>"$TMP/err"
code $? 2 "resuming into a file of another grid exits 2"
has "$TMP/err" "written by another sweep" "the message says why"

# ---- a failed point is recorded; the sweep goes on ----
# (axial 0 N under a 500 N radial load is ill-posed for one angular-contact
# bearing: a cross-field rule, so that point's failure, not the grid's)
"$ACBB" sweep "$PRESET" --set fidelity.model=quasi-static --set operating.radial_load_N=500 \
    --grid operating.axial_load_N=300,0,600 --grid thermal.max_steps=3,20000 \
    --jsonl "$TMP/fail.jsonl" >"$TMP/out" 2>"$TMP/err"
code $? 3 "a sweep with failed points exits 3"
jq -s -e '.[1:] | length == 6 and (map(.index) | sort == [0,1,2,3,4,5])' "$TMP/fail.jsonl" >/dev/null 2>&1
t $? "every point recorded, failed ones too"
jq -s -e 'map(select(.grid["operating.axial_load_N"] == 0)) | length == 2 and
    all(.[]; .status == "ill_posed" and (.message | test("needs axial_load_N >=")) and ."losses_W.total" == null)' \
    "$TMP/fail.jsonl" >/dev/null 2>&1
t $? "the ill-posed combination: status ill_posed, the rule in the message, results null"
jq -s -e 'map(select(.grid["operating.axial_load_N"] != 0)) |
    (map(select(.grid["thermal.max_steps"] == 3)) | all(.[]; .status == "not_converged" and .iterations == 3))
    and (map(select(.grid["thermal.max_steps"] == 20000)) | all(.[]; .status == "converged"))' \
    "$TMP/fail.jsonl" >/dev/null 2>&1
t $? "the step limit: not_converged after 3 steps; the others converged"

# ---- a bearing set: its set.* metrics in every record (MODEL.md 14) ----
# A 2-D sweep of a rigid DB pair over speed x preload: every point converges,
# carries its own assembly preload, and the preload heat adds grows with the
# speed at each assembly preload (the rings warm more); CSV = JSONL.
# The seed's physics (MODEL.md 14's sign: the inner ring hotter than the
# outer squeezes a rigid set). Under the reference profile's moving-source
# contact heat the 400 N pair at 8000 rpm runs at 380 N: the spacers' axial
# growth outweighs the radial squeeze there (README "Physics profiles").
"$ACBB" sweep presets/pair-rigid-16k.ini --grid operating.inner_speed_rpm=8000:16000:3 \
    --grid mounting.preload_N=200,400 --set physics.profile=seed --jobs 2 \
    --jsonl "$TMP/pair.jsonl" --csv "$TMP/pair.csv" >"$TMP/out" 2>"$TMP/err"
code $? 0 "a 2-D sweep of a DB pair over speed x preload"
jq -s -e '.[1:] | length == 6 and all(.[]; .status == "converged"
    and .["set.preload_assembly_N"] == .grid["mounting.preload_N"]
    and .["set.preload_N"] > .["set.preload_assembly_N"]
    and .["set.stiffness_axial_N_per_um"] > 0 and .["set.liftoff_thrust_N"] > 0)' \
    "$TMP/pair.jsonl" >/dev/null 2>&1
t $? "each point: converged, set.preload_assembly_N = its grid preload, heat adds preload"
jq -s -e '.[1:] | group_by(.grid["mounting.preload_N"]) | all(.[];
    sort_by(.grid["operating.inner_speed_rpm"]) | map(.["set.preload_N"])
    | . as $p | [range(1; length)] | all(.[]; $p[.] > $p[. - 1]))' "$TMP/pair.jsonl" >/dev/null 2>&1
t $? "the set's preload rises with speed at each assembly preload"
col=$(sed -n 1p "$TMP/pair.csv" | tr , '\n' | grep -nx 'set.preload_N' | cut -d: -f1)
want=$(jq -s '.[1:] | map(select(.index == 5))[0]["set.preload_N"]' "$TMP/pair.jsonl")
got=$(awk -F, -v c="$col" '$1 == "5" { print $c }' "$TMP/pair.csv")
[ -n "$col" ] && awk -v a="$got" -v b="$want" 'BEGIN { d = a - b; exit !(d < 1e-6 * b && d > -1e-6 * b) }'
t $? "CSV column set.preload_N (column $col) = the JSONL value ($got)"
# One bearing: no set keys in its JSONL records, empty set columns in CSV.
"$ACBB" sweep "$PRESET" --grid operating.axial_load_N=300 --jsonl "$TMP/one1.jsonl" \
    --csv "$TMP/one1.csv" >"$TMP/out" 2>"$TMP/err"
tail -1 "$TMP/one1.jsonl" | jq -e '[keys[] | select(startswith("set."))] | length == 0' >/dev/null 2>&1 &&
    [ "$(awk -F, -v c="$col" 'NR == 2 { print $c }' "$TMP/one1.csv")" = "" ]
t $? "a single bearing's records: no set keys (JSONL), empty set columns (CSV)"

# ---- bad grids are refused before anything runs ----
# A value its key refuses fails at every point that has it: a typo, exit 2
# before anything runs, naming the value (issue 26 item 11; it was exit 3).
"$ACBB" sweep "$PRESET" --grid operating.axial_load_N=300,-5 --grid effects.thermal_expansion=on,of \
    --jsonl "$TMP/typo.jsonl" >"$TMP/out" 2>"$TMP/err"
code $? 2 "a grid value out of its key's range exits 2"
has "$TMP/err" "--grid operating.axial_load_N, value 2 of 2: operating.axial_load_N = -5: must be >= 0 N" \
    "... naming the key, the value and the range"
"$ACBB" sweep "$PRESET" --grid operating.axial_load_N=300 --grid effects.thermal_expansion=on,of \
    --jsonl "$TMP/typo.jsonl" >"$TMP/out" 2>"$TMP/err"
code $? 2 "a typo in a grid value (of for off) exits 2"
has "$TMP/err" "effects.thermal_expansion = of: must be on or off" "... naming the value"
[ ! -e "$TMP/typo.jsonl" ]
t $? "... and nothing was written (not even a header)"
for g in operating.axial_load_N operating.nosuch=1,2 operating.axial_load_N=1:2 \
         operating.axial_load_N=1:2:0 operating.axial_load_N=1,,2; do
    "$ACBB" sweep "$PRESET" --grid "$g" --jsonl "$TMP/never.jsonl" >"$TMP/out" 2>"$TMP/err"
    code $? 2 "--grid $g is refused"
done
[ ! -s "$TMP/never.jsonl" ]
t $? "... and nothing was written"
"$ACBB" sweep "$PRESET" --grid operating.axial_load_N=1 --shard 4/3 >"$TMP/out" 2>"$TMP/err"
code $? 2 "--shard 4/3 is refused"
has "$TMP/err" "expected K/N with 1 <= K <= N" "the message gives the form"

tap_done
