#!/bin/sh
# `acbb new`: presets from bearing designations (TAP). $1 = the acbb binary;
# cwd = repository root. Checks the written files against the ISO 15
# boundary dimensions, the estimate markers, `acbb check` on them, the
# shipped 7008C preset's geometry, the explicit form and refusals.
set -u

ACBB=${1:?usage: test_new.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-new.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
XDG_CONFIG_HOME="$TMP/xdg"
export XDG_CONFIG_HOME

. "$(dirname "$0")/tap.sh"

# val FILE KEY: the value of KEY (first match) in an INI file.
val() { sed -n "s/^$2 = //p" "$1" | head -n 1; }

# near GOT WANT RTOL NAME: |GOT - WANT| <= RTOL |WANT|.
near() {
    awk -v g="$1" -v w="$2" -v r="$3" 'BEGIN { d = g - w; if (d < 0) d = -d;
        exit !(g != "" && d <= r * (w < 0 ? -w : w)) }'
    t $? "$4 (got $1, want $2 within $3)"
}

# ---- the designation form: files written with the ISO 15 dimensions ----
# bore mm, outside mm, width mm for each (ISO 15 dimension series 10, 02, 18).
for row in "7000C 10 26 8" "7008C 40 68 15" "7020AC 100 150 24" "7040B 200 310 51" \
           "6205 25 52 15" "71810C 50 65 7" "6220 100 180 34"; do
    set -- $row
    (cd "$TMP" && "$ACBB" new "$1" >"$TMP/out" 2>"$TMP/err")
    code $? 0 "new $1"
    f="$TMP/$1.ini"
    [ -s "$f" ]; t $? "$1: $1.ini written"
    [ "$(val "$f" bore_mm)" = "$2" ] && [ "$(val "$f" outer_diameter_mm)" = "$3" ] &&
        [ "$(val "$f" width_mm)" = "$4" ]
    t $? "$1: d x D x B = $2 x $3 x $4 mm"
    grep -B1 '^ball_diameter_mm = ' "$f" | grep -q '^; estimated:'
    t $? "$1: the ball diameter is marked estimated"
    [ "$(val "$f" profile)" = reference ] && [ "$(val "$f" rolling_hysteresis)" = johnson ] &&
        [ "$(val "$f" loss_ehl_rolling)" = on ] && [ "$(val "$f" loss_cage)" = on ]
    t $? "$1: states physics.profile = reference and its keys (issue 25)"
    "$ACBB" check "$f" >"$TMP/out" 2>"$TMP/err"
    rc=$?
    # The thermal network's surroundings are still the seed's fixed-size
    # test rig (MODEL.md 13): a bearing that does not fit it is refused by
    # the network, not by the scene. Skipped until the network scales.
    if [ $rc -ne 0 ] && grep -q '^acbb: network:' "$TMP/err"; then
        skip "$1: acbb check passes" "$(head -c 90 "$TMP/err")"
    else
        code $rc 0 "$1: acbb check passes"
    fi
done

# ---- a wider cross-check of the boundary-dimension table ----
# d x D x B from the SKF rolling bearings catalogue (PUB BU/P1 17000 EN,
# 2018) deep-groove tables, read independently of the table in
# src/scene/designation.c: all five diameter series, small to large bores.
bad=""
for row in "6000 10 26 8" "6200 10 30 9" "6300 10 35 11" "61800 10 19 5" "61900 10 22 6" \
           "6004 20 42 12" "6304 20 52 15" "61804 20 32 7" "61904 20 37 9" "6008 40 68 15" \
           "6010 50 80 16" "61810 50 65 7" "61910 50 72 12" "6310 50 110 27" "6212 60 110 22" \
           "6315 75 160 37" "6017 85 130 22" "6217 85 150 28" "6317 85 180 41" "6222 110 200 38" \
           "6322 110 240 50" "6028 140 210 33" "6228 140 250 42" "6328 140 300 62" \
           "61828 140 175 18" "61928 140 190 24" "6030 150 225 35" "6230 150 270 45" \
           "6330 150 320 65" "61830 150 190 20" "61930 150 210 28" "6036 180 280 46" \
           "6040 200 310 51" "6240 200 360 58" "7340B 200 420 80" "7220B 100 180 34"; do
    set -- $row
    "$ACBB" new "$1" --out - >"$TMP/dims" 2>/dev/null
    got="$(val "$TMP/dims" bore_mm) $(val "$TMP/dims" outer_diameter_mm) $(val "$TMP/dims" width_mm)"
    [ "$got" = "$2 $3 $4" ] || bad="$bad $1($got, catalogue $2 $3 $4)"
done
[ -z "$bad" ]; t $? "36 designations match the catalogue's d x D x B${bad:+:$bad}"

# ---- angles and clearance ----
[ "$(val "$TMP/7000C.ini" contact_angle_deg)" = 15 ]; t $? "7000C: contact angle 15 deg (C)"
[ "$(val "$TMP/7020AC.ini" contact_angle_deg)" = 25 ]; t $? "7020AC: contact angle 25 deg (AC)"
[ "$(val "$TMP/7040B.ini" contact_angle_deg)" = 40 ]; t $? "7040B: contact angle 40 deg (B)"
[ "$(val "$TMP/6205.ini" contact_angle_deg)" = 0 ]; t $? "6205: deep groove, angle 0"
# ISO 5753-1 group N for a 25 mm bore: 5..20 um, middle 12.5.
[ "$(val "$TMP/6205.ini" clearance_um)" = 12.5 ]; t $? "6205: clearance 12.5 um (CN middle)"
grep -B1 '^clearance_um = ' "$TMP/6205.ini" | grep -q '^; estimated:'
t $? "6205: the clearance is marked estimated"

# ---- 7008C from its designation vs the shipped (seed) preset ----
P=presets/7008C.ini
for k in bore_mm outer_diameter_mm width_mm pitch_diameter_mm contact_angle_deg; do
    near "$(val "$TMP/7008C.ini" $k)" "$(val $P $k)" 1e-9 "7008C: $k as the shipped preset"
done
# The ball set NSK CAT. No. E1102e implies for 7008 C (f_0 = 15.4, C_0r =
# 15 900 N inverted through ISO 76: 17 balls of 7.938 mm), and its ratings
# (C_r 20 600 N, C_0r 15 900 N) from the estimated internals (docs/ratings.md).
[ "$(val "$TMP/7008C.ini" ball_diameter_mm)" = 7.938 ] && [ "$(val "$TMP/7008C.ini" n_balls)" = 17 ]
t $? "7008C: 17 balls of 7.938 mm, as the NSK catalogue's f_0 and C_0 imply"
grep -B1 '^inner_shoulder_mm = ' "$TMP/7008C.ini" | grep -q '^; estimated:' &&
    grep -B1 '^inner_speed_rpm = ' "$TMP/7008C.ini" | grep -q '^; estimated:'
t $? "7008C: shoulder height and default speed are marked estimated"
[ "$(val "$TMP/7008C.ini" internals_estimated)" = on ]; t $? "7008C: life.internals_estimated = on"
(cd "$TMP" && "$ACBB" run 7008C.ini --set operating.inner_speed_rpm=6000 --json >run.json 2>err)
code $? 0 "the generated 7008C preset runs to steady state"
near "$(jq .life.C_N "$TMP/run.json")" 20600 0.02 "7008C: C within 2 % of the catalogue's"
near "$(jq .life.C0_N "$TMP/run.json")" 15900 0.01 "7008C: C0 within 1 % of the catalogue's"
jq -e '.life.estimated == true' "$TMP/run.json" >/dev/null; t $? "7008C: the life says estimated"

# ---- the explicit form ----
(cd "$TMP" && "$ACBB" new --series 70 --bore 70 --angle 15 --out explicit.ini >out 2>err)
code $? 0 "new --series 70 --bore 70 --angle 15"
(cd "$TMP" && "$ACBB" new 7014C >out 2>err)
cmp -s "$TMP/explicit.ini" "$TMP/7014C.ini"; t $? "the explicit form writes what 7014C writes"

# ---- refusals ----
(cd "$TMP" && "$ACBB" new 7008C >out 2>err)
code $? 2 "an existing file is never overwritten"
has "$TMP/err" "exists" "  and the message says so"
"$ACBB" new 7014 --out "$TMP/x.ini" >/dev/null 2>"$TMP/err"
code $? 2 "7014 without an angle suffix refused"
has "$TMP/err" "angle suffix" "  message names the suffix"
"$ACBB" new 7023C --out "$TMP/x.ini" >/dev/null 2>"$TMP/err"
code $? 2 "bore 115 mm refused"
has "$TMP/err" "ISO 15" "  message names the table"
"$ACBB" new --series 62 --bore 25 --angle 15 --out "$TMP/x.ini" >/dev/null 2>"$TMP/err"
code $? 2 "a deep-groove series with an angle refused"
[ ! -e "$TMP/x.ini" ]; t $? "nothing written on a refusal"

# Bores 10, 40, 100 and 200 mm made by `acbb new` run to thermal steady
# state in their derived surroundings, energy balanced (speeds kept to
# a n*dm of about 0.6-1.2e6 mm/min, a usual limit for oil-air). The 7000C
# carries 300 N: at the default 1000 N its 70 W run away in derived
# (convective, issue 18) surroundings of about 0.3 W/K.
for spec in 7000C:20000:300 7008C:15000:1000 7020C:6000:1000 7040C:3000:1000; do
    name=${spec%%:*}; rest=${spec#*:}; rpm=${rest%%:*}; load=${rest##*:}
    "$ACBB" new "$name" --out "$TMP/run-$name.ini" >/dev/null 2>&1
    "$ACBB" run "$TMP/run-$name.ini" --set operating.inner_speed_rpm="$rpm" \
        --set operating.axial_load_N="$load" --json \
        >"$TMP/run-$name.json" 2>/dev/null
    jq -e '.status == "converged" and .energy_W.in > 0
        and ((.energy_W.in - .energy_W.out) | if . < 0 then -. else . end) < 1e-6 * .energy_W.in' \
        "$TMP/run-$name.json" >/dev/null
    t $? "$name (bore $(jq -r '.scene.keys["bearing.bore_mm"]' "$TMP/run-$name.json") mm) at $rpm rpm: converged, heat in = heat out"
done

tap_done
