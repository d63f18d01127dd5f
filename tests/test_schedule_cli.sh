#!/usr/bin/env bash
# Run-in schedules and two branches from the command line (MODEL.md 14):
# `acbb run`'s branches (JSON and table), the schedule object and progress
# line, a ramp that crosses into runaway, `acbb edit` keeping the rows, and
# the messages of bad rows. $1 = the acbb binary.
. "$(dirname "$0")/tap.sh"
ACBB=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# No NaN/Inf anywhere in a JSON document (jq reads them as null or fails).
finite() { jq -e '[.. | numbers] | all(isinfinite | not)' "$1" >/dev/null 2>&1 && ! grep -qi 'nan\|null' "$1"; }

# A step start at 16 000 rpm under rigid preload: branches automatic. The
# 143 N is MODEL.md 14's, the seed physics' (the preset states reference).
"$ACBB" run presets/runaway-rigid-preload.ini --set physics.profile=seed --json \
    >"$TMP/step.json" 2>"$TMP/err"
t $([ $? -eq 3 ]; echo $?) "runaway preset: exit 3 (the run ran away)"
jqt "$TMP/step.json" '.status == "runaway" and .branches.agree == false
    and .branches.transient.status == "runaway" and .branches.steady.status == "converged"
    and (.branches.steady.Qi_N - 143 | abs) < 1.5 and .branches.transient.Qi_N > 400' \
    "runaway preset: JSON branches disagree (steady Qi ~143 N, transient ran away)"
jqt "$TMP/step.json" '.branches.max_dT_K > 10 and (.branches.criterion | test("0.01 K"))' \
    "  with the difference and the criterion"
jqt "$TMP/step.json" 'has("schedule") | not' "  no schedule object without a [schedule]"
finite "$TMP/step.json"
t $? "  every number finite"

"$ACBB" run presets/runaway-rigid-preload.ini >"$TMP/step.txt" 2>/dev/null
grep -q '^branches     DIFFERENT: steady solve and transient end on different branches$' \
    "$TMP/step.txt" && grep -q '^transient runaway  ' "$TMP/step.txt" &&
    grep -q '^steady    converged  ' "$TMP/step.txt" &&
    grep -q '^          the transient ran to t = [0-9.]* s simulated$' "$TMP/step.txt"
t $? "runaway preset: the table says DIFFERENT, both states listed"

# The staged run-in: one branch, schedule finished.
"$ACBB" run presets/run-in-ramp.ini --json >"$TMP/ramp.json" 2>/dev/null
t $? "run-in-ramp: exit 0"
jqt "$TMP/ramp.json" '.status == "converged" and .branches.agree == true
    and .schedule.finished == true and .schedule.row == 6 and .schedule.n_rows == 6
    and .schedule.inner_speed_rpm == 16000 and (.schedule.rows | length) == 6
    and .schedule.rows[1] == {"t_s": 120, "inner_speed_rpm": 8000, "axial_load_N": 1000,
                              "radial_load_N": 0}
    and .time_s > .schedule.end_s' \
    "run-in-ramp: converged, branches agree, schedule finished at row 6/6"
jqt "$TMP/ramp.json" '(.balls[0].Qi_N - .branches.steady.Qi_N | abs) < 1e-5' \
    "  its Qi is the steady solve's"
"$ACBB" run presets/run-in-ramp.ini >"$TMP/ramp.txt" 2>/dev/null
grep -q '^scene        16000 rpm' "$TMP/ramp.txt" \
    && grep -q '^schedule     row 6/6 at 16000 rpm, Fx 1000 N, Fr 0 N, finished' "$TMP/ramp.txt" \
    && grep -q '^branches     the steady solve and the transient reach the same state' "$TMP/ramp.txt"
t $? "run-in-ramp table: scene at the last row, schedule line, one branch"

# Force preload, no schedule: no second solve unless asked.
"$ACBB" run presets/teaching-7node.ini --json >"$TMP/t7.json" 2>/dev/null
jqt "$TMP/t7.json" 'has("branches") | not' "force preload, no schedule: no branches object"
"$ACBB" run presets/teaching-7node.ini --branches --json >"$TMP/t7b.json" 2>/dev/null
jqt "$TMP/t7b.json" '.branches.agree == true and .branches.loss_rel < 1e-6' \
    "--branches on a benign scene: one branch"

# The progress line shows the row and the speed while the schedule runs.
ACBB_PROGRESS=1 "$ACBB" run presets/run-in-ramp.ini --quiet 2>"$TMP/prog" >/dev/null
tr '\r' '\n' <"$TMP/prog" | grep -Eq 'row [1-6]/6 [0-9]+ rpm'
t $? "progress line: schedule row k/6 and speed"

# A one-minute ramp crosses into the runaway: named status, last good state.
# The seed's physics (stationary contact spots, MODEL.md 14's two
# branches): under the reference profile's moving-source contact heat the
# ramp converges (README "Physics profiles").
cp presets/run-in-ramp.ini "$TMP/fast.ini"
sed -i '/^row = [1-9]/d' "$TMP/fast.ini"
echo 'row = 60, 16000, 1000, 0' >>"$TMP/fast.ini"
"$ACBB" run "$TMP/fast.ini" --set physics.profile=seed --json >"$TMP/fast.json" 2>/dev/null
t $([ $? -eq 3 ]; echo $?) "60 s ramp: exit 3"
jqt "$TMP/fast.json" '.status == "runaway" and .schedule.finished == true
    and .branches.agree == false and .losses_W.total > 0' \
    "60 s ramp: runaway after the ramp, another branch than the steady solve"
finite "$TMP/fast.json"
t $? "  every number finite"

# acbb edit keeps the rows (and their comments) byte for byte.
cp presets/run-in-ramp.ini "$TMP/ed.ini"
"$ACBB" edit "$TMP/ed.ini" --set operating.ambient_C=20 >/dev/null 2>&1
diff <(sed -n '/^\[schedule\]/,$p' presets/run-in-ramp.ini) \
     <(sed -n '/^\[schedule\]/,/^\[operating\]/p' "$TMP/ed.ini" | sed '/^$/d; /^\[operating\]/d') \
    >/dev/null
t $? "acbb edit: the [schedule] section unchanged"

# --set schedule.rows: every row at once (';' between rows); "" removes them.
cp presets/runaway-rigid-preload.ini "$TMP/new.ini"
"$ACBB" edit "$TMP/new.ini" --set 'schedule.rows=0, 0, 1000, 0; 600, 16000, 1000, 0' >/dev/null 2>&1
[ "$(sed -n '/^\[schedule\]/,$p' "$TMP/new.ini")" = "$(printf '[schedule]\nrow = 0, 0, 1000, 0\nrow = 600, 16000, 1000, 0')" ]
t $? "acbb edit --set schedule.rows writes a [schedule] section"
"$ACBB" run "$TMP/new.ini" --json >"$TMP/new.json" 2>/dev/null
jqt "$TMP/new.json" '.status == "converged" and .branches.agree == true' \
    "  a 600 s ramp to 16000 rpm: converged, the steady solve's branch"
"$ACBB" edit "$TMP/new.ini" --set 'schedule.rows=' >/dev/null 2>&1
"$ACBB" run "$TMP/new.ini" --json >"$TMP/new0.json" 2>/dev/null
jqt "$TMP/new0.json" '.status == "runaway" and (has("schedule") | not)' \
    "  schedule.rows= removes the rows: the step start runs away again"
"$ACBB" check "$TMP/new.ini" --set 'schedule.rows=0,0,1000,0;0,5,1000,0' 2>"$TMP/err" >/dev/null
t $([ $? -eq 2 ]; echo $?) "--set schedule.rows with equal times: exit 2"
grep -q "schedule row 2 (t = 0 s): times must increase strictly" "$TMP/err"
t $? "  with the row and the rule"

# Bad rows: exit 2, file:line, the rule.
printf '[schedule]\nrow = 0, 0, 1000, 0\nrow = 10, 200000, 1000, 0\n' >"$TMP/bad.ini"
"$ACBB" check "$TMP/bad.ini" 2>"$TMP/err" >/dev/null
t $([ $? -eq 2 ]; echo $?) "bad speed in a row: exit 2"
grep -q "bad.ini:3: schedule.row = 10, 200000, 1000, 0: column 2 is operating.inner_speed_rpm = 200000: must be between 0 and 100000 rpm" "$TMP/err"
t $? "  message: file:line, key, rule and unit"
printf '[schedule]\nrow = 0, 0, 1000, 0\nrow = 10, 0, 100, 500\n' >"$TMP/bad2.ini"
"$ACBB" check "$TMP/bad2.ini" 2>"$TMP/err" >/dev/null
t $([ $? -eq 2 ]; echo $?) "radial row without enough thrust: exit 2"
grep -q "bad2.ini:3: schedule row 2 (t = 10 s): operating.radial_load_N = 500 with axial_load_N = 100" "$TMP/err"
t $? "  message: the row's line and the ill-posed rule"

tap_done
