#!/bin/sh
# The full `acbb report --sensitivity` (TAP; slow suite, about 2000 runs):
# every uncertain input at each end of its plausible range, the whole check
# table re-judged. Checks the bookkeeping (every item once, every input and
# end accounted for, JSON = text = Markdown) and, against an independent
# code path, the sign numbers: the one-at-a-time `acbb sensitivity` of
# P_T(TE) - P_T(WTE) at 15000 rpm, 1000 N must turn condition 1 at exactly
# the same ends with the same numbers. $1 = path of the acbb binary.
set -u

ACBB=${1:?usage: test_report_sens.sh path/to/acbb}
PRESET=presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-report-sens.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM

. "$(dirname "$0")/tap.sh"

"$ACBB" report "$PRESET" --sensitivity --json --md "$TMP/SEED.md" >"$TMP/sens.json" 2>"$TMP/err"
code $? 0 "report --sensitivity --json runs"
# The keys with a plausible range, less the spindle's sections (a bearing
# scene has no shaft, housing, motor or spindle to vary: left out).
n_in=$("$ACBB" keys | awk '/^[a-z_]+\.[A-Za-z_0-9]+ = / { sec = $1; sub(/\..*/, "", sec) }
    /^ *plausible:/ { if (sec !~ /^(shaft|housing|motor|spindle)$/) n++ } END { print n + 0 }')
jq -e --argjson n "$n_in" 'length == 18 and all(.[]; .robustness.inputs == $n)' "$TMP/sens.json" >/dev/null 2>&1
t $? "every item's robustness covers all $n_in uncertain inputs (acbb keys)"
# An end is varied unless it is the scene's own value (two-level inputs at their first choice).
same=$("$ACBB" keys | awk '/^[a-z_]+\.[A-Za-z_0-9]+ = / { v = $3; sec = $1; sub(/\..*/, "", sec) }
    /^ *plausible:/ { if (sec !~ /^(shaft|housing|motor|spindle)$/ && ($2 == v "" || $2 == "[" v "," || $3 == v "]" || $4 == v ";")) s++ } END { print s + 0 }')
jq -e --argjson n "$n_in" --argjson s "$same" 'all(.[]; .robustness.ends == 2 * $n - $s)' "$TMP/sens.json" >/dev/null 2>&1
t $? "ends = 2 x $n_in inputs - $same at the scene's own value"
jq -e 'all(.[]; (.item == 18) == (.robustness.varied | not))' "$TMP/sens.json" >/dev/null 2>&1
t $? "items 1-17 varied, item 18 (sanity) not"
jq -e 'all(.[]; .robustness.turned == (.robustness.changes | any(.turns_item)))' "$TMP/sens.json" >/dev/null 2>&1
t $? "an item is 'turned' exactly when one of its changes turns its verdict"

# Condition 1 (P_T(TE) - P_T(WTE) > 0 at 1000 N) against `acbb sensitivity`.
"$ACBB" sensitivity "$PRESET" --set operating.inner_speed_rpm=15000 --set operating.axial_load_N=1000 \
    --metric losses_W.total --delta thermal_expansion --json >"$TMP/oat.json" 2>/dev/null
code $? 0 "acbb sensitivity of P_T TE - WTE at 15000 rpm, 1000 N runs"
jq -r '.inputs[] | (select(.at_low > 0 and .low != .base) | "\(.key)=\(.low) \(.at_low)"),
                   (select(.at_high > 0 and .high != .base) | "\(.key)=\(.high) \(.at_high)")' \
    "$TMP/oat.json" | sort >"$TMP/want.txt"
jq -r '.[0].robustness.conditions[0].turned_by[] | "\(.key)=\(.value) \(.at)"' "$TMP/sens.json" |
    sort >"$TMP/got.txt"
# The same ends; the numbers to 1e-5: the study's 1000 N TE point is its
# recorded transient, `acbb sensitivity` runs the steady solve (batch.h),
# and the two steady states differ by ~5e-9 of P_T (~3e-7 W of a 0.09 W
# difference).
[ -s "$TMP/want.txt" ] && [ "$(cut -d' ' -f1 "$TMP/want.txt")" = "$(cut -d' ' -f1 "$TMP/got.txt")" ] &&
    paste -d' ' "$TMP/want.txt" "$TMP/got.txt" | awk '{ d = $2 - $4; if (d < 0) d = -d
        if (d > 1e-5 * ($2 < 0 ? -$2 : $2)) bad = 1 } END { exit bad }'
t $? "condition 1 turns at the same $(wc -l <"$TMP/want.txt") ends with the same numbers (1e-5) as acbb sensitivity"

"$ACBB" report "$PRESET" --sensitivity >"$TMP/sens.txt" 2>"$TMP/err"
code $? 0 "report --sensitivity (text) runs"
sed -n '/^Robustness (--sensitivity/,/^The TE - WTE differences/p' "$TMP/sens.txt" |
    grep -E '^ {0,2}[0-9]{1,2}  (HELD|NOT HELD|NOT EVALUATED); ' >"$TMP/items.txt"
awk '{print $1}' "$TMP/items.txt" >"$TMP/nums.txt"
seq 1 18 >"$TMP/want18.txt"
cmp -s "$TMP/nums.txt" "$TMP/want18.txt"
t $? "the text lists items 1..18 once each"
sed -E 's/^ *([0-9]+)  (HELD|NOT HELD|NOT EVALUATED);.*/\1 \2/' "$TMP/items.txt" >"$TMP/tv.txt"
jq -r '.[] | "\(.item) \(.verdict)"' "$TMP/sens.json" >"$TMP/jv.txt"
cmp -s "$TMP/tv.txt" "$TMP/jv.txt"
t $? "text and JSON agree on every verdict"
awk 'length > 80 { bad = 1 } END { exit bad }' "$TMP/sens.txt"
t $? "the text fits 80 columns"
[ "$(sed -n '/^## Robustness/,/^### /p' "$TMP/SEED.md" | grep -c -E '^\| [0-9]+ \| (HELD|NOT HELD|NOT EVALUATED) \|')" -eq 18 ]
t $? "the Markdown robustness table has 18 item rows"
# (item 18's statement says "dt -> inf": words, not a number)
jq -e '[.. | strings | gsub("-> inf "; " ") | select(test("(^|[^a-z_])-?(nan|inf)([^a-z_]|$)"))] | length == 0' \
    "$TMP/sens.json" >/dev/null 2>&1
t $? "no nan/inf in any JSON text"

tap_done
