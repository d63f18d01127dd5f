#!/bin/sh
# The spindle's preset keys from the command line (issue 31; docs/spindle.md
# "Scene"): `acbb keys` lists the four sections whole, `acbb check` passes
# the spindle presets and refuses a broken one with the file's name and the
# rule's message, names a spindle key that does nothing, and `acbb edit`
# saves a spindle key into the user's file and refuses an edit that breaks
# a rule. TAP. $1 = acbb; cwd = repository root.
set -u
ACBB=${1:?usage: test_spindle_scene_cli.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-spindle-scene.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

"$ACBB" keys >"$TMP/keys" 2>"$TMP/err"
code $? 0 "acbb keys"
for want in shaft:27 housing:27 motor:5 spindle:16; do
    sec=${want%%:*} count=${want#*:}   # not n: tap.sh counts with it
    got=$(grep -c "^$sec\.[A-Za-z0-9_]* = " "$TMP/keys")
    [ "$got" -eq "$count" ]
    t $? "acbb keys lists the $count keys of [$sec] ($got)"
done
grep -q '^spindle.rear_support = spring$' "$TMP/keys" &&
    grep -A1 '^spindle.rear_support = ' "$TMP/keys" | grep -q 'fixed | spring | floating'
t $? "acbb keys: rear_support's default and choices"
grep -A1 '^shaft.segments = 0$' "$TMP/keys" | grep -q '\[0, 8\]'
t $? "acbb keys: shaft.segments defaults to 0 (no spindle), interval [0, 8]"

for p in presets/spindle-belt-DB.ini presets/spindle-motor-DBT.ini; do
    "$ACBB" check "$p" >"$TMP/out" 2>"$TMP/err"
    code $? 0 "acbb check $p"
done

sed 's/^rear_x_mm = 250$/rear_x_mm = 200/' presets/spindle-belt-DB.ini >"$TMP/bad.ini"
(cd "$TMP" && "$ACBB" check bad.ini >/dev/null 2>err)
code $? 2 "acbb check: a rear bearing moved off its seat is refused"
has "$TMP/err" "acbb: bad.ini: shaft.seg3_od_mm = 48 at the rear set's bearing 1 (centre 200 mm) with bearing.bore_mm = 40: the inner rings sit on the shaft, so its outer diameter there must equal the bearing's bore (within 0.01 mm)" \
    "  with the file's name and the seat rule's message"

"$ACBB" check presets/7008C.ini --set spindle.coolant_cells=4 >/dev/null 2>"$TMP/err"
code $? 0 "acbb check: a spindle key on a bearing scene is valid"
has "$TMP/err" "note: shaft.seg*_mm, shaft.n_div, shaft.end_film_W_m2K, housing.*, motor.*, spindle.* has no effect here: shaft.segments = 0 is no spindle" \
    "  and said to have no effect"

# A single front set with a displacement preload in a spindle: the nose
# thrust acts through the shaft (the rule that sends a lone bearing's thrust
# to the fixture is not a spindle's; it said "no effect" while the front
# set's load went 106 -> 336 N)
"$ACBB" check presets/spindle-belt-DB.ini --set spindle.rear_support=fixed --set set.arrangement=single \
    --set spindle.rear_arrangement=single --set spindle.rear_preload_N=200 \
    --set mounting.preload=displacement --set operating.axial_load_N=300 >/dev/null 2>"$TMP/err"
code $? 0 "acbb check: a single front set with a displacement preload and a nose thrust"
! grep -q "operating.axial_load_N has no effect" "$TMP/err"
t $? "  the nose thrust is not said to have no effect ($(head -c 200 "$TMP/err"))"

cp presets/spindle-belt-DB.ini "$TMP/e.ini"
"$ACBB" edit "$TMP/e.ini" --set spindle.rear_friction_N=100 >/dev/null 2>"$TMP/err"
code $? 0 "acbb edit: a spindle key"
grep -qx 'rear_friction_N = 100' "$TMP/e.ini" && [ "$(grep -c '^rear_friction_N' "$TMP/e.ini")" -eq 1 ]
t $? "  rewrites its line in the user's file"
"$ACBB" edit "$TMP/e.ini" --set motor.x1_mm=10 >/dev/null 2>"$TMP/err"
code $? 2 "acbb edit: a motor span off the housing is refused"
has "$TMP/err" "motor.x0_mm = 0, x1_mm = 10: the motor (0 to 10 mm) must lie on the housing (28 to 264 mm)" \
    "  with the span rule's message"
! grep -q '^\[motor\]' "$TMP/e.ini"
t $? "  and the file is left as it was"
tap_done
