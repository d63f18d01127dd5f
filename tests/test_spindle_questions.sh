#!/usr/bin/env bash
# The commands docs/spindle.md "Questions a spindle answers" gives, on the
# spindle presets, through `acbb sweep` (steady solve, a few points):
# the spindle columns (--metric) present and finite on every converged
# point and on a runaway one; the trends the answers read from them (more
# coolant flow: a cooler coolant outlet and a smaller nose drift; more
# front preload: a stiffer nose and a front set running at more preload;
# more sleeve friction: more thrust on the front pair, the rear carrying at
# most the friction; none: the rear lifted off); a speed sweep's status turning from converged to
# runaway where the docs say; a 2-D grid sharded in two and merged (the
# Slurm job array's path) equal byte for byte to the grid run whole.
# $1 = the acbb binary.
. "$(dirname "$0")/tap.sh"
ACBB=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
MOTOR=presets/spindle-motor-DBT.ini
BELT=presets/spindle-belt-DB.ini
M=(--metric spindle.nose_drift_um --metric spindle.nose_stiffness_N_per_um
   --metric 'spindle.sets[0].preload_N' --metric 'spindle.sets[0].axial_N'
   --metric 'spindle.sets[1].axial_N' --metric spindle.coolant_C.outlet)

# sweep NAME PRESET GRID...: the points as JSON lines in $TMP/NAME.jsonl.
sweep() {
    local name=$1 preset=$2
    shift 2
    "$ACBB" sweep "$preset" "$@" "${M[@]}" --jobs 1 --jsonl "$TMP/$name.jsonl" \
        >/dev/null 2>"$TMP/err"
    local rc=$?
    points "$name"
    return $rc
}
# points NAME: the point records of $TMP/NAME.jsonl (its header line out).
points() { jq -c 'select(.index != null)' "$TMP/$1.jsonl" >"$TMP/$1.pts"; }
# at NAME KEY VALUE PATH: PATH of the point whose grid KEY is VALUE.
at() {
    jq -s --arg k "$2" --argjson v "$3" ".[] | select(.grid[\$k] == \$v) | .[\"$4\"]" \
        "$TMP/$1.pts"
}
# trend NAME KEY LO HI PATH COND TEXT: COND holds for a = PATH at KEY = HI
# and b = PATH at KEY = LO (an awk expression), both numbers.
trend() {
    local b a
    b=$(at "$1" "$2" "$3" "$5")
    a=$(at "$1" "$2" "$4" "$5")
    awk -v a="$a" -v b="$b" "BEGIN { n = \"^-?[0-9]\"
        exit !(a ~ n && b ~ n && ($6)) }"
    t $? "$7: $a at $4, $b at $3"
}
finite='[.[] | select(.status == "converged" or .status == "runaway")
         | [."spindle.nose_drift_um", ."spindle.nose_stiffness_N_per_um",
            ."spindle.sets[0].preload_N", ."spindle.sets[0].axial_N",
            ."spindle.sets[1].axial_N", ."spindle.coolant_C.outlet"]
         | all(type == "number")] | all'

sweep flow "$MOTOR" --grid spindle.coolant_flow_l_min=1,8
code $? 0 "motor spindle: sweep over coolant flow"
jq -s -e "($finite) and length == 2" "$TMP/flow.pts" >/dev/null
t $? "coolant flow: the spindle columns present and finite on both points"
trend flow spindle.coolant_flow_l_min 1 8 spindle.coolant_C.outlet 'a < b' \
    "more coolant flow: a cooler outlet (C)"
trend flow spindle.coolant_flow_l_min 1 8 spindle.nose_drift_um 'a > 0 && a < b' \
    "more coolant flow: a smaller nose drift (um)"

sweep preload "$MOTOR" --grid mounting.preload_N=150,600
code $? 0 "motor spindle: sweep over front preload"
trend preload mounting.preload_N 150 600 spindle.nose_stiffness_N_per_um 'a > b' \
    "more front preload: a stiffer nose (N/um)"
trend preload mounting.preload_N 150 600 'spindle.sets[0].preload_N' 'a > b && b > 150' \
    "more front preload: the front set runs at more, above its assembly (N)"

sweep friction "$BELT" --grid spindle.rear_friction_N=0,40,400
code $? 0 "belt spindle: sweep over the rear sleeve's friction"
jq -s -e "($finite) and length == 3 and all(.status == \"converged\")" "$TMP/friction.pts" >/dev/null
t $? "sleeve friction: all three points converged, spindle columns finite"
# Without friction the sleeve passes no thrust: the single rear bearing
# carries nothing, so it has no contact (lifted off), and the run says so.
jq -s -e '.[] | select(.grid["spindle.rear_friction_N"] == 0)
          | (.message | contains("rear set bearing 0: contact_lost (lifted off)"))
            and ."spindle.sets[1].axial_N" == 0' "$TMP/friction.pts" >/dev/null
t $? "no sleeve friction: the rear bearing carries nothing and is reported lifted off"
jq -s -e '[.[] | (."spindle.sets[1].axial_N" | if . < 0 then -. else . end)
                 <= .grid["spindle.rear_friction_N"] * (1 + 1e-9)] | all' \
    "$TMP/friction.pts" >/dev/null
t $? "the floating rear carries at most its friction"
f40=$(at friction spindle.rear_friction_N 40 'spindle.sets[0].axial_N')
f400=$(at friction spindle.rear_friction_N 400 'spindle.sets[0].axial_N')
awk -v a="$f400" -v b="$f40" 'BEGIN { if (a < 0) a = -a; if (b < 0) b = -b; exit !(a > b) }'
t $? "more friction: more thrust on the front pair ($f400 N at 400 N, $f40 N at 40)"

# The runaway speed docs/spindle.md reports lies between 14000 rpm
# (converged) and 16000 rpm (runaway): its coarse sweep's bracket (steady
# solve; the 100 rpm refinement, converged to 14800 and runaway from 14900,
# is slower to run and moves with the solver's path near the edge).
sweep speed "$MOTOR" --grid operating.inner_speed_rpm=14000,16000
jq -s -e '(map({(.grid["operating.inner_speed_rpm"] | tostring): .status}) | add)
          == {"14000": "converged", "16000": "runaway"}' "$TMP/speed.pts" >/dev/null
t $? "speed sweep: converged at 14000 rpm, runaway at 16000 rpm ($(jq -s -c 'map(.status)' "$TMP/speed.pts"))"
jq -s -e "$finite" "$TMP/speed.pts" >/dev/null
t $? "speed sweep: the runaway point's spindle columns finite (its last state)"
# The runaway names a real place past the limit: a set's bearing and node,
# or a shaft or housing cell whose centre lies on that part (the preset:
# shaft 0-330 mm from the nose, housing 22-296 mm).
msg=$(jq -s -r '.[] | select(.status == "runaway") | .message' "$TMP/speed.pts")
place='^thermal runaway: ((front|rear) set: bearing [0-9]+ node [0-9]+ [a-z ]+|(shaft|housing) cell at x = [0-9.]+ mm) reached 1[5-9][0-9]\.[0-9] C \(limit thermal\.temp_limit_C = 150 C\)'
x=$(sed -n 's/^thermal runaway: \(shaft\|housing\) cell at x = \([0-9.]*\) mm.*/\1 \2/p' <<<"$msg")
echo "$msg" | grep -E -q "$place" && awk -v p="${x% *}" -v x="${x#* }" 'BEGIN {
    exit !(p == "" || (p == "shaft" && x > 0 && x < 330) || (p == "housing" && x > 22 && x < 296)) }'
t $? "the runaway names where it starts ($msg)"

# The Slurm job array runs shards (--shard K/N) and merges them.
G=(--grid mounting.preload_N=150,300 --grid spindle.coolant_flow_l_min=1,4)
for k in 1 2; do
    "$ACBB" sweep "$MOTOR" "${G[@]}" "${M[@]}" --shard $k/2 --jobs 1 --csv "$TMP/s$k.csv" \
        >/dev/null 2>"$TMP/err"
    code $? 0 "2-D sweep, shard $k/2"
done
"$ACBB" merge "$TMP/merged.csv" "$TMP/s1.csv" "$TMP/s2.csv" 2>"$TMP/err"
code $? 0 "the shards merge"
"$ACBB" sweep "$MOTOR" "${G[@]}" "${M[@]}" --jobs 1 --csv "$TMP/whole.csv" >/dev/null 2>"$TMP/err"
"$ACBB" merge "$TMP/whole-m.csv" "$TMP/whole.csv" 2>"$TMP/err"
cmp -s "$TMP/merged.csv" "$TMP/whole-m.csv"
t $? "sharded and merged = the grid run whole, byte for byte"
[ "$(wc -l <"$TMP/merged.csv")" -eq 5 ] && head -1 "$TMP/merged.csv" | grep -q 'spindle.nose_drift_um'
t $? "the merged table: 4 points and the spindle columns"
tap_done
