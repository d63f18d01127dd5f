#!/bin/sh
# The preload window's skid floor where it binds (issue 19 item 4): a
# spring-preloaded 7008C at 20 000 rpm (presets/preload-window-spring.ini,
# every traction value at its MODEL.md default). The criterion of
# include/acbb/tools/preload_map.h is recomputed here, outside the engine, from
# the ball speeds and loads `acbb run --json` prints for each preload of the
# grid:  skid = max_j J |omega_m| sqrt(omega_y'^2 + omega_z'^2) / (mu Q_i D/2),
# J = m D^2 / 10, m = rho pi D^3 / 6 (MODEL.md 3), mu = the limiting shear
# ratio; the map's lowest preload inside the window must be the first grid
# preload whose recomputed ratio is <= 1. And on the rigid mounting of the
# same bearing the ratio stays under 1 (why the spring scene exists). TAP.
# $1 = the acbb binary; cwd = repository root.
set -u
ACBB=${1:?usage: test_life_skid.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-life-skid.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

P=presets/preload-window-spring.ini
RPM=20000
"$ACBB" preload-map $P --spring --speeds $RPM:$RPM:1 --preloads 10:250:13 --jobs 2 \
    --csv "$TMP/map.csv" >"$TMP/map.txt" 2>"$TMP/err"
code $? 0 "preload-map --spring runs"
lo=$(awk -v s=$RPM '$1 == s && $NF != "none" { print $(NF - 2) }' "$TMP/map.txt")
[ -n "$lo" ]; t $? "the map has a window at $RPM rpm (lower edge ${lo:-none} N)"

# The criterion by hand, from acbb run's JSON, at every preload of the grid.
first_free=""
skids=0
agree=0
for F in 10 30 50 70 90 110 130 150 170 190 210 230 250; do
    "$ACBB" run $P --set mounting.preload=force --set operating.axial_load_N=$F \
        --set operating.inner_speed_rpm=$RPM --json >"$TMP/run.json" 2>/dev/null
    r=$(jq '.scene.keys as $k | ($k["bearing.ball_diameter_mm"] / 1000) as $D
            | ($k["materials.ball_density_kg_m3"] * 3.141592653589793 * $D * $D * $D / 6) as $m
            | ($m * $D * $D / 10) as $J | $k["lubricant.limiting_shear_ratio"] as $mu
            | [.balls[] | $J * (.omega_m_radps | fabs)
               * ((.omega_y_radps * .omega_y_radps + .omega_z_radps * .omega_z_radps) | sqrt)
               / ($mu * .Qi_N * $D / 2)] | max' "$TMP/run.json")
    m=$(awk -F, -v f=$F 'NR > 1 && $2 == f { print $5 }' "$TMP/map.csv")
    echo "# $F N: skid by hand $r, map $m"
    awk -v a="$r" -v b="$m" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(b != "" && d <= 1e-6 * a) }' \
        && agree=$((agree + 1))
    if awk -v a="$r" 'BEGIN { exit !(a > 1) }'; then skids=$((skids + 1))
    elif [ -z "$first_free" ]; then first_free=$F; fi
done
[ "$agree" -eq 13 ]; t $? "each cell's skid ratio is the one recomputed from acbb run --json ($agree of 13)"
[ "$skids" -gt 0 ] && [ -n "$first_free" ]
t $? "the skid limit lies inside the grid ($skids preloads skid, the first free at ${first_free:-none} N)"
[ "$lo" = "$first_free" ]; t $? "the window's lower edge ($lo N) is that first skid-free preload"
awk -F, -v f="$first_free" 'NR > 1 && $2 + 0 < f + 0 && $4 != "skid" { bad = 1 } END { exit bad }' \
    "$TMP/map.csv"
t $? "every lighter preload is flagged skid"

# The same bearing on a rigid mounting: the held preload's inner contact
# load grows with speed, and the ratio stays under 1 at the lightest preload.
"$ACBB" preload-map $P --speeds $RPM:$RPM:1 --preloads 10:10:1 --csv "$TMP/rigid.csv" \
    >/dev/null 2>"$TMP/err"
code $? 0 "the rigid map runs"
awk -F, 'NR == 2 { exit !($5 < 1 && $4 == "ok") }' "$TMP/rigid.csv"
t $? "rigid 10 N at $RPM rpm: no skid ($(awk -F, 'NR == 2 { print $5 }' "$TMP/rigid.csv"))"

"$ACBB" preload-map presets/pair-rigid-16k.ini --spring --speeds 1000:1000:1 --preloads 1:1:1 \
    >/dev/null 2>"$TMP/err"
code $? 2 "--spring on a bearing set is refused"
has "$TMP/err" "a spring preload maps a single bearing" "  with the reason"

tap_done
