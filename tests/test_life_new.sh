#!/bin/sh
# Presets made by `acbb new` run at their own default operating point
# (issue 19, src/scene/designation.c): each converges, its life object is
# there and marked estimated, its static safety exceeds 1 (a load of 5 % of
# C0 cannot pass 4200 MPa) and its speed is the stated n d_m. TAP.
# $1 = the acbb binary; $2 = "all" (every series, bore and angle: 640
# presets, the `slow` suite) or "sample" (the 200 mm bore of every series
# and angle, where the old default point failed: 20 presets). cwd = repository root.
set -u
ACBB=${1:?usage: test_life_new.sh path/to/acbb all|sample}
WHICH=${2:-sample}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-life-new.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

if [ "$WHICH" = all ]; then
    bores="00 01 02 03 04 05 06 07 08 09 10 11 12 13 14 15 16 17 18 19 20 21 22 24 26 28 30 32 34 36 38 40"
else
    bores="40"
fi
list=""
for s in 70 72 73 718 719; do
    for b in $bores; do for a in C AC B; do list="$list $s$b$a"; done; done
done
for s in 60 62 63 618 619; do for b in $bores; do list="$list $s$b"; done; done

# One designation: "NAME STATUS OK|why" (run by xargs, two at a time).
cat >"$TMP/one.sh" <<'ONE'
#!/bin/sh
d=$1; dir=$2; acbb=$3
"$acbb" new "$d" --out "$dir/$d.ini" >/dev/null 2>"$dir/$d.err" || { echo "$d new-failed"; exit 0; }
"$acbb" run "$dir/$d.ini" --json >"$dir/$d.json" 2>>"$dir/$d.err"
jq -r --arg d "$d" '
  (.scene.keys["bearing.pitch_diameter_mm"] | tonumber) as $dm
  | (.scene.keys["operating.inner_speed_rpm"] * $dm) as $ndm
  | [$d, .status,
     (if .status != "converged" then "not converged: " + .message
      elif (.life.estimated | not) then "life not marked estimated"
      elif .life.s0_min <= 1 then "s0_min \(.life.s0_min)"
      elif .life.L10r_h <= 0 then "L10r_h \(.life.L10r_h)"
      elif ($ndm < 0.1e6 or $ndm > 0.3e6) then "n d_m \($ndm)"
      else "ok" end)] | join(" ")' "$dir/$d.json" 2>/dev/null || echo "$d no-json"
ONE
chmod +x "$TMP/one.sh"
total=$(echo $list | wc -w)
echo $list | tr ' ' '\n' | xargs -P 2 -I{} "$TMP/one.sh" {} "$TMP" "$ACBB" >"$TMP/results"
good=$(grep -c ' ok$' "$TMP/results")
bad=$(grep -v ' ok$' "$TMP/results" | head -n 5 | tr '\n' ';')
[ "$good" -eq "$total" ]
t $? "$good of $total generated presets converge at their default point, life estimated, s0 > 1, n d_m as stated${bad:+: $bad}"
tap_done
