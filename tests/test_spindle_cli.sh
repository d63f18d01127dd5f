#!/usr/bin/env bash
# A spindle end to end (issue 31): every presets/spindle-*.ini through
# `acbb run`. The run document validates against the schema
# (python3-jsonschema), holds no null (the writer's mark of a non-finite
# number), and has the names scripts rely on with plausible values:
# spindle.nose_drift_um a number, spindle.nose_stiffness_N_per_um > 0,
# spindle.sets[].preload_N of the front set > 0 and equal to the front
# set's set.preload_N; each set's arrays one per bearing; the heat balance
# closes at a steady state. The text output's spindle block keeps within
# 80 columns and prints the JSON's numbers; --csv has the spindle columns. Skipped while no spindle preset
# exists. $1 = the acbb binary; SPINDLE_PRESETS="a.ini b.ini" runs others.
. "$(dirname "$0")/tap.sh"
ACBB=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
PY=""
for c in /usr/bin/python3 python3; do
    "$c" -c 'import jsonschema' 2>/dev/null && { PY=$c; break; }
done

presets=${SPINDLE_PRESETS:-$(ls presets/spindle-*.ini 2>/dev/null)}
if [ -z "$presets" ]; then
    skip "a spindle preset end to end" "no presets/spindle-*.ini yet"
    tap_done
    exit $?
fi

for p in $presets; do
    pn=$(basename "$p" .ini)
    J="$TMP/$pn.json"
    "$ACBB" run "$p" --json --csv "$TMP/$pn.csv" >"$J" 2>"$TMP/err"
    code $? 0 "$pn: acbb run --json --csv"
    jqt "$J" '.status == "converged"' "$pn: converged ($(jq -r '.status + ": " + .message' "$J" | head -c 120))"
    if [ -n "$PY" ]; then
        $PY tests/schema_check.py docs/schema/acbb.schema.json "$J" 2>"$TMP/bad"
        t $? "$pn: the run document validates against the schema $(head -3 "$TMP/bad" | cut -c1-200 | tr '\n' ' ')"
    else
        skip "$pn: the run document validates against the schema" "no python3 jsonschema"
    fi
    jqt "$J" '[.. | select(. == null)] | length == 0' \
        "$pn: no null in the document (every number finite; $(jq -c '[paths(. == null) | map(tostring) | join(".")] | .[:3]' "$J"))"
    jqt "$J" '.spindle.nose_drift_um | type == "number"' \
        "$pn: spindle.nose_drift_um is a number ($(jq '.spindle.nose_drift_um' "$J") um)"
    jqt "$J" '.spindle.nose_stiffness_N_per_um > 0 and .spindle.nose_axial_stiffness_N_per_um > 0' \
        "$pn: the nose's radial and axial stiffness are > 0 ($(jq -c '[.spindle.nose_stiffness_N_per_um, .spindle.nose_axial_stiffness_N_per_um]' "$J") N/um)"
    jqt "$J" '.spindle.sets | length == 2 and .[0].position == "front" and .[1].position == "rear"
              and .[0].x_mm < .[1].x_mm' "$pn: sets[] is the front set, then the rear one behind it"
    jqt "$J" '.spindle.sets[0].preload_N > 0 and .spindle.sets[0].preload_N == .set.preload_N' \
        "$pn: spindle.sets[0].preload_N > 0, the front set's set.preload_N ($(jq -c '[.spindle.sets[].preload_N]' "$J") N)"
    jqt "$J" '[.spindle.sets[] | (.Q_max_N | length) == .bearings
               and (.contact_angle_inner_deg | length) == .bearings] | all' \
        "$pn: each set's arrays have one number per bearing"
    jqt "$J" '[.spindle.shaft, .spindle.housing | (.x_mm | length) == (.T_C | length)
               and (.x_mm | length) > 0] | all' \
        "$pn: shaft and housing profiles ($(jq -c '[.spindle.shaft.x_mm, .spindle.housing.x_mm | length]' "$J") cells)"
    # at a steady state (converged, above) the heat made leaves:
    # motor + bearings = coolant + air
    jqt "$J" '.spindle.heat_W | (.motor + .bearings) as $in | ($in - .coolant - .air | abs)
              <= 0.01 * $in + 1e-6' \
        "$pn: the heat balance closes at a steady state ($(jq -c '.spindle.heat_W' "$J"))"

    # the text block: within 80 columns, the JSON's numbers (%.4g)
    "$ACBB" run "$p" >"$TMP/$pn.txt" 2>"$TMP/err"
    sed -n '/^spindle  /,/^$/p' "$TMP/$pn.txt" >"$TMP/block"
    w=$(awk '{ if (length($0) > w) w = length($0) } END { print w + 0 }' "$TMP/block")
    [ -s "$TMP/block" ] && [ "$w" -le 80 ]
    t $? "$pn: the text output has a spindle block at most 80 columns wide ($w)"
    sed 's/^/# /' "$TMP/block"
    drift=$(jq '.spindle.nose_drift_um' "$J")
    k=$(jq '.spindle.nose_stiffness_N_per_um' "$J")
    pre=$(jq '.spindle.sets[0].preload_N' "$J")
    has "$TMP/block" "nose drift   axial $(LC_ALL=C printf '%.4g' "$drift") um" \
        "$pn: the block's nose drift is the JSON's"
    has "$TMP/block" "nose stiff   radial $(LC_ALL=C printf '%.4g' "$k") N/um" \
        "$pn: the block's nose stiffness is the JSON's"
    # the set's own stiffness is not presented as the nose's (a set's line
    # says "at the nose" only outside a spindle: the shaft bends)
    ! grep -E -q "^stiffness .* at the nose" "$TMP/$pn.txt" && grep -q "(set alone)" "$TMP/$pn.txt"
    t $? "$pn: the set's stiffness line says it is the set alone's, not the nose's"
    grep -E -q "^front +$(LC_ALL=C printf '%.1f' "$pre") " "$TMP/block"
    t $? "$pn: the block's front set preload is the JSON's ($(LC_ALL=C printf '%.1f' "$pre") N)"

    # --csv: the warm-up curve's columns, a number in each of every row
    awk -F, 'NR == 1 { n = NF; for (i = 1; i <= NF; i++) if ($i ~ /^spindle\./) c[++m] = i; next }
             NF != n { exit 1 } { for (j = 1; j <= m; j++) if ($c[j] == "") exit 1 }
             END { if (m != 8 || NR < 2) exit 1 }' "$TMP/$pn.csv"
    t $? "$pn: run --csv has the 8 spindle columns, a number in each of its $(($(wc -l <"$TMP/$pn.csv") - 1)) rows"
done
tap_done
