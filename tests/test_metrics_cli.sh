#!/usr/bin/env bash
# `acbb metrics`: the output table's listing (outputs.h). Every line is
# "PATH UNIT LABEL"; known rows carry their units; an unknown --metric
# points at the listing. (test_outputs checks every path against the JSON.)
# $1 = the acbb binary.
. "$(dirname "$0")/tap.sh"
ACBB=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

"$ACBB" metrics >"$TMP/out" 2>"$TMP/err"
code $? 0 "acbb metrics runs"
grep -E -q '^ring\.stiffness_axial_N_per_um +N/um +axial stiffness$' "$TMP/out"
t $? "ring.stiffness_axial_N_per_um is listed in N/um"
grep -E -q '^ring\.stiffness_tilt_Nm_per_mrad +N m/mrad ' "$TMP/out"
t $? "the tilt stiffness is in N m/mrad (a unit with a blank)"
grep -E -q '^balls\[i\]\.slide_i_mps +m/s ' "$TMP/out"
t $? "balls[i].slide_i_mps is in m/s"
grep -E -q '^losses_W\.spin +W +spinning$' "$TMP/out"
t $? "a loss of the loss table is listed with its label"
# Every line after the heading: a path, a unit, a label; a label too long
# for 80 columns goes on under itself (column 44), and no line is wider.
# (a spindle set's index is a number: spindle.sets[0].preload_N)
wide=$( (awk 'length > 80' "$TMP/out"; grep '^ ' "$TMP/out" | grep -E -v '^ {43}[^ ]') | wc -l)
[ "$wide" -eq 0 ] && grep -q -x ' \{43\}radially' "$TMP/out"
t $? "80 columns: long labels go on under their column ($wide lines wider or misplaced)"
bad=$(tail -n +2 "$TMP/out" | grep -v '^ ' | awk '$1 !~ /^[a-zA-Z_]+(\[i\])?(\.[a-zA-Z_][a-zA-Z0-9_]*(\[[01]\])?)+$/ || NF < 3' | wc -l)
rows=$(tail -n +2 "$TMP/out" | wc -l)
[ "$bad" -eq 0 ] && [ "$rows" -gt 50 ]
t $? "$rows rows, each a path with a unit and a label ($bad malformed)"
# The spindle's results (issue 31), under the run JSON's names.
grep -E -q '^spindle\.nose_drift_um +um ' "$TMP/out" &&
    grep -E -q '^spindle\.nose_stiffness_N_per_um +N/um +radial ' "$TMP/out" &&
    grep -E -q '^spindle\.sets\[0\]\.preload_N +N +front set: ' "$TMP/out" &&
    grep -E -q '^spindle\.sets\[1\]\.preload_N +N +rear set: ' "$TMP/out" &&
    grep -E -q '^spindle\.coolant_C\.outlet +C ' "$TMP/out"
t $? "the spindle's nose drift, radial nose stiffness, each set's preload and coolant outlet are listed"
# ... and a scene that is not a spindle has no value for them: a
# sensitivity of one says so instead of computing effects on zeros
"$ACBB" sensitivity presets/7008C.ini --metric spindle.nose_drift_um >/dev/null 2>"$TMP/err"
code $? 2 "sensitivity --metric spindle.nose_drift_um of 7008C is bad input"
grep -q "metric spindle.nose_drift_um has no value here: the scene is not a spindle" "$TMP/err"
t $? "... saying the scene is not a spindle, before any run ($(head -c 200 "$TMP/err"))"
"$ACBB" help metrics >"$TMP/help" 2>&1
has "$TMP/help" "--metric" "acbb help metrics says what the names are for"
"$ACBB" help >"$TMP/help" 2>&1
has "$TMP/help" "metrics" "the overview lists the command"
"$ACBB" metrics extra >/dev/null 2>"$TMP/err"
code $? 2 "acbb metrics takes no arguments"
# An unknown metric points the user at the listing.
"$ACBB" sensitivity presets/7008C.ini --metric ring.nope >/dev/null 2>"$TMP/err"
code $? 2 "an unknown metric is bad input"
has "$TMP/err" "acbb metrics" "its message names acbb metrics"
tap_done
