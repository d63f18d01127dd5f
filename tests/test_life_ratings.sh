#!/bin/sh
# docs/ratings.md (issue 19 item 3) against the tool: for every designation
# of its table, `acbb new` + `acbb run --json` (standing, so only the
# geometry counts) must give the C and C0 the table prints (0.1 kN), its
# ratios must be those of the catalogue column, every row names its
# catalogue source, and there are at least 20 rows. TAP. $1 = the acbb
# binary; cwd = repository root.
set -u
ACBB=${1:?usage: test_life_ratings.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-life-ratings.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

# designation | C est | C cat | C ratio | C0 est | C0 cat | C0 ratio | source
awk -F'|' '/^\| [0-9]/ { for (i = 2; i <= 10; i++) gsub(/^ +| +$/, "", $i);
           print $2 "|" $4 "|" $5 "|" $6 "|" $7 "|" $8 "|" $9 "|" $10 }' docs/ratings.md \
    >"$TMP/rows"
rows=$(wc -l <"$TMP/rows")
[ "$rows" -ge 20 ]; t $? "the table has at least 20 designations ($rows)"
grep -q "n = $rows\$" docs/ratings.md; t $? "its summary line counts them (n = $rows)"
awk -F'|' '$8 !~ /(SKF|NSK).*line/ { bad = 1 } END { exit bad }' "$TMP/rows"
t $? "every row names its catalogue and the line of the row"

bad=""
while IFS='|' read -r d c ccat cr c0 c0cat c0r src; do
    "$ACBB" new "$d" --out "$TMP/$d.ini" >/dev/null 2>&1 &&
        "$ACBB" run "$TMP/$d.ini" --set operating.inner_speed_rpm=0 --json >"$TMP/$d.json" 2>/dev/null
    got=$(jq -r '[.life.C_N, .life.C0_N] | @tsv' "$TMP/$d.json" 2>/dev/null)
    awk -v g="$got" -v c="$c" -v ccat="$ccat" -v cr="$cr" -v c0="$c0" -v c0cat="$c0cat" \
        -v c0r="$c0r" 'BEGIN { split(g, v, "\t"); C = v[1] / 1000; C0 = v[2] / 1000;
            ok = sprintf("%.1f", C) == c && sprintf("%.1f", C0) == c0 &&
                 sprintf("%.2f", C / ccat) == cr && sprintf("%.2f", C0 / c0cat) == c0r;
            exit !ok }' || bad="$bad $d($got)"
done <"$TMP/rows"
[ -z "$bad" ]; t $? "every row's C, C0 and ratios are acbb's own${bad:+; differ:$bad}"

tap_done
