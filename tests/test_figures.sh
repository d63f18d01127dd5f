#!/bin/sh
# End-to-end test of `acbb study seed --out DIR` (TAP): the seed's Figs.
# 7-19. $1 = path of the acbb binary; cwd = repository root. Needs jq and
# gnuplot (skipped with the reason when gnuplot is missing). Checks that
# every panel REPORT.md lists exists as a complete PNG (ends with IEND), a
# complete SVG (ends with </svg>) and a CSV with at least two finite data
# rows, that REPORT.md links all three, that every seed figure 7-19 has a
# section, that the verdict lines agree with `acbb report --json`, and the
# exit statuses of a bad --out and of a missing gnuplot.
set -u

ACBB=${1:?usage: test_figures.sh path/to/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-figures.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM

. "$(dirname "$0")/tap.sh"

OUT="$TMP/out"
if ! command -v "${ACBB_GNUPLOT:-gnuplot}" >/dev/null 2>&1; then
    skip "study seed --out writes the seed's figures" "gnuplot not installed"
    tap_done
    exit $?
fi

# One study serves every check below, the --size one included (a second
# full study only for the PNG size cost the suite seconds).
"$ACBB" study seed --out "$OUT" --size 640x400 >"$TMP/stdout" 2>"$TMP/err"
code $? 0 "study seed --out DIR --size 640x400 runs"
[ -s "$OUT/REPORT.md" ]
t $? "REPORT.md written"

# Panel rows: "| figNN... | title | [PNG](...) ... |" or "| ... | not computed | why |".
grep -E '^\| fig[0-9]{2}[a-z0-9]* \|' "$OUT/REPORT.md" | awk -F'|' '{gsub(/ /, "", $2); print $2}' \
    >"$TMP/ids"
[ "$(wc -l <"$TMP/ids")" -ge 30 ]
t $? "REPORT.md lists the panels ($(wc -l <"$TMP/ids") of them)"
! grep -q ' | not computed | ' "$OUT/REPORT.md"
t $? "every panel was computed (default preset)"

# One check per panel: the three files complete, the data finite, the links.
while read -r id; do
    bad=""
    [ "$(tail -c 8 "$OUT/$id.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = "49454e44ae426082" ] \
        || bad="$bad png"
    tail -c 16 "$OUT/$id.svg" 2>/dev/null | grep -q '</svg>' || bad="$bad svg"
    # Data rows: skip comments and the header; x and y must be plain finite numbers.
    rows=$(awk -F, '/^#/ || NR == 0 { next } !hdr { hdr = 1; next }
        { if ($2 !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ || $3 !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) bad++; n++ }
        END { print (bad ? -1 : n + 0) }' "$OUT/$id.csv" 2>/dev/null)
    [ "${rows:--1}" -ge 2 ] || bad="$bad csv($rows)"
    head -3 "$OUT/$id.csv" | grep -q '^series,.*(.*),.*(.*)$' || bad="$bad csv-header"
    for l in "[PNG]($id.png)" "[SVG]($id.svg)" "[data]($id.csv)"; do
        grep -F -q "$l" "$OUT/REPORT.md" || bad="$bad link:$l"
    done
    [ -z "$bad" ]
    t $? "$id: complete PNG and SVG, $rows finite data rows, linked${bad:+ (bad:$bad)}"
done <"$TMP/ids"

[ "$(ls "$OUT"/fig*.png | wc -l)" -eq "$(wc -l <"$TMP/ids")" ]
t $? "no image that REPORT.md does not list"

for f in 7 8 9 10 11 12 13 14 15 16 17 18 19; do
    grep -q "^## Fig. $f\$" "$OUT/REPORT.md" || echo "$f" >>"$TMP/missing"
done
[ ! -s "$TMP/missing" ]
t $? "a section for each of the seed's Figs. 7-19"

# Verdicts: "- Item N: VERDICT - statement" against acbb report --json.
# One report gives the JSON (stdout) and the Markdown (--md) compared below.
"$ACBB" report presets/7008C.ini --json --md "$TMP/report.md" >"$TMP/report.json" 2>"$TMP/err"
code $? 0 "acbb report --json --md runs"
jq -r '.[] | "\(.item) \(.verdict)"' "$TMP/report.json" | sort >"$TMP/want"
sed -n 's/^- Item \([0-9]*\): \(HELD\|NOT HELD\|NOT EVALUATED\) - .*/\1 \2/p' "$OUT/REPORT.md" \
    | sort -u >"$TMP/got"
[ -s "$TMP/got" ] && join "$TMP/got" "$TMP/want" >/dev/null && \
    [ "$(join -v1 "$TMP/got" "$TMP/want" | wc -l)" -eq 0 ]
t $? "each verdict line of REPORT.md is the verdict acbb report gives ($(wc -l <"$TMP/got") items)"
[ "$(wc -l <"$TMP/got")" -ge 15 ]
t $? "REPORT.md cites at least 15 of the 18 statements"

# The seed's seven conclusions, with the verdicts acbb report gives (issue 21 item 11).
grep -q "^## Seed conclusions (seed section 5)" "$OUT/REPORT.md"
t $? "REPORT.md has the seed's conclusions"
sed -n 's/^| (\([0-9]\)) | \(HELD\|NOT HELD\|NOT EVALUATED\) | .*/\1 \2/p' "$OUT/REPORT.md" >"$TMP/cgot"
[ "$(wc -l <"$TMP/cgot")" -eq 7 ]
t $? "all seven are listed ($(wc -l <"$TMP/cgot"))"
sed -n 's/^| (\([0-9]\)) | \(HELD\|NOT HELD\|NOT EVALUATED\) | .*/\1 \2/p' "$TMP/report.md" |
    awk '!seen[$1]++' >"$TMP/cwant" # the first table; the by-mounting one follows
[ -s "$TMP/cwant" ] && cmp -s "$TMP/cgot" "$TMP/cwant"
t $? "with the verdicts of acbb report --md"

# ---- fit to print (issue 21 item 9), read from the SVGs ----
grep -q "ω" "$OUT/fig08a.svg" && ! grep -q "omega_x'" "$OUT/fig08a.svg"
t $? "fig08a: omega_x' is printed as the Greek letter with a subscript"
grep -q "°C" "$OUT/fig07b.svg" && ! grep -q "(C)" "$OUT/fig07b.svg"
t $? "fig07b: the temperature axis says degrees C"
grep -q '<tspan[^>]*dy="[0-9.]*px">T</tspan>' "$OUT/fig13a.svg" && ! grep -q "P_T" "$OUT/fig13a.svg"
t $? "fig13a: P_T has a real subscript"
cols=$(grep -o "stroke='rgb([^']*)'" "$OUT/fig13a.svg" | sort -u | wc -l)
[ "$cols" -ge 2 ]
t $? "fig13a: TE and WTE are drawn in different colours ($cols line colours)"
grep -q "stroke-dasharray" "$OUT/fig13a.svg"
t $? "fig13a: and WTE is dashed"
# the size: PNG width and height from the IHDR chunk (bytes 17-24)
[ "$(od -An -tu1 -j16 -N8 "$OUT/fig13a.png" | tr -s ' ' | sed 's/^ //')" = "0 0 2 128 0 0 1 144" ]
t $? "--size 640x400: the PNGs are 640 x 400 pixels"
"$ACBB" study seed --out "$TMP/bad" --size 10x10 >/dev/null 2>"$TMP/err"
code $? 2 "--size 10x10 is refused with exit 2"
grep -q "size" "$TMP/err"
t $? "and says why: $(head -1 "$TMP/err")"

# ---- failures ----
: >"$TMP/file"
"$ACBB" study seed --out "$TMP/file" >/dev/null 2>"$TMP/err"
code $? 2 "--out naming a regular file is refused"
grep -q 'not a directory' "$TMP/err"
t $? "and the message says why"

ACBB_GNUPLOT="$TMP/no-such-gnuplot" "$ACBB" study seed --out "$TMP/nogp" >/dev/null 2>"$TMP/err"
code $? 4 "a missing gnuplot is exit 4"
grep -q 'not computed.*not found' "$TMP/nogp/REPORT.md" 2>/dev/null
t $? "and REPORT.md lists the panels as not computed, with the reason"

tap_done
