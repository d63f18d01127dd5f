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
# A gnuplot that keeps a copy of each script it is sent (issue 29 item 9:
# what gnuplot is asked to draw is checked below).
mkdir "$TMP/gp"
GP=$(command -v "${ACBB_GNUPLOT:-gnuplot}")
printf '#!/bin/sh\nf=$(mktemp "%s/gp/s.XXXXXX")\ntee "$f" | "%s"\n' "$TMP" "$GP" >"$TMP/gpwrap"
chmod +x "$TMP/gpwrap"
ACBB_GNUPLOT="$TMP/gpwrap" "$ACBB" study seed --out "$OUT" --size 640x400 >"$TMP/stdout" 2>"$TMP/err"
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
# "| (n) | conclusion | force | rigid | DB | holds under |": the verdicts
# under the three mountings, against acbb report --md's table by mounting.
V='HELD\|NOT HELD\|NOT EVALUATED'
sed -n "s/^| (\([0-9]\)) | [^|]* | \($V\) | \($V\) | \($V\) | \([^|]*\) |\$/\1 \2 \3 \4 \5/p" \
    "$OUT/REPORT.md" >"$TMP/cgot"
[ "$(wc -l <"$TMP/cgot")" -eq 7 ]
t $? "all seven are listed with a verdict per mounting ($(wc -l <"$TMP/cgot"))"
sed -n "s/^| (\([0-9]\)) | \($V\) | \($V\) | \($V\) | \([^|]*\) |\$/\1 \2 \3 \4 \5/p" \
    "$TMP/report.md" >"$TMP/cwant"
[ -s "$TMP/cwant" ] && cmp -s "$TMP/cgot" "$TMP/cwant"
t $? "the constant force / rigid preload / DB pair table of acbb report --md"
# issue 29 item 10: each conclusion with its numbers and the reason, and no
# check named that the report does not define.
for c in 1 2 3 4 5 6 7; do
    sed -n "/^### ($c) /,/^##/p" "$OUT/REPORT.md" | sed 1d >"$TMP/c$c"
    grep -q '^Why:' "$TMP/c$c" && grep -q 'it is \(HELD\|NOT HELD\)' "$TMP/c$c" &&
        grep -q '[0-9][0-9.]* \(N\|rpm\|%\|W\|rad/s\|m/s\)' "$TMP/c$c"
    t $? "conclusion ($c): a reason (Why:, a verdict per mounting) and numbers with units"
done
grep -o '[Cc]heck [0-9][0-9]*[a-z]' "$OUT/REPORT.md" | sed 's/^[Cc]heck //' | sort -u >"$TMP/used"
grep -o '^Check [0-9]*[a-z] is a test of statement [0-9]*' "$OUT/REPORT.md" |
    awk '{ print $2 }' | sort -u >"$TMP/defined"
[ -s "$TMP/used" ] && [ -z "$(comm -23 "$TMP/used" "$TMP/defined")" ]
t $? "every check REPORT.md names is defined ($(wc -l <"$TMP/used") named; undefined:" \
  "$(comm -23 "$TMP/used" "$TMP/defined" | tr '\n' ' '))"
grep -q 'Note (fig17c).*changes sign' "$OUT/REPORT.md"
t $? "conclusion (6) says omega_so of fig17c reverses sign (check 16c reads it signed)"

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

# ---- what gnuplot is asked to draw (issue 29 item 9) ----
ls "$TMP"/gp/s.* >"$TMP/scripts" 2>/dev/null
[ "$(wc -l <"$TMP/scripts")" -eq "$(wc -l <"$TMP/ids")" ]
t $? "one gnuplot script per panel ($(wc -l <"$TMP/scripts"))"
bad=""
while read -r f; do
    # text: the em at 640 px printed 8.5 cm wide is 8.5 pt (pngcairo takes 3/4 of it)
    pt=$(sed -n "s/^set terminal pngcairo .*size \([0-9]*\),[0-9]* font 'sans,\([0-9.]*\)'.*/\2 \1/p" "$f" |
         awk '{ printf "%.2f", $1 / 0.75 / $2 * 241 }')
    awk -v p="${pt:-0}" 'BEGIN { exit !(p >= 8 && p <= 9.5) }' || bad="$bad $f:font=$pt"
    grep -E "^set (x|y)label" "$f" | grep -qv "(.*)" && bad="$bad $f:label-without-unit"
    grep -iE "^set title.*(fig[0-9]|seed fig|L2|ball 0)" "$f" >/dev/null && bad="$bad $f:title"
    grep -E "_\{[^}]*\} " "$f" >/dev/null && bad="$bad $f:space-after-subscript"
    grep -qE "^set key (inside (top|bottom) (left|right)|outside below)" "$f" || bad="$bad $f:key"
    grep "^plot " "$f" | grep -q "dashtype" || bad="$bad $f:dash"
    # a quantity never negative has no negative axis
    awk '/^\$S[0-9]+ << EOD/ { d = 1; next } /^EOD/ { d = 0 } d && $2 < m { m = $2 }
         /^set yrange \[/ { v = $0; sub(/^set yrange \[/, "", v); lo = v + 0; seen = 1 }
         END { exit !(seen && (m < 0 || lo >= 0)) }' m=0 "$f" || bad="$bad $f:negative-axis"
done <"$TMP/scripts"
[ -z "$bad" ]
t $? "every panel: text 8-9.5 pt at column width, axis labels with units, titles without" \
  "file names, a key clear of the data, dashes, no negative axis for a positive" \
  "quantity${bad:+ (bad:$bad)}"
f=$(grep -l "^set title 'Outer-ring temperature rise" $(cat "$TMP/scripts") | head -1)
shapes=$(grep "^plot " "$f" | grep -o "pointtype [0-9]*" | sort -u | wc -l)
[ "$shapes" -ge 8 ]
t $? "fig07a: the eight loads have eight marker shapes ($shapes), not colour alone"
grep -q "F_{x}" "$f" $(cat "$TMP/scripts") && grep -q "T_{5}" $(cat "$TMP/scripts")
t $? "F_x and T_5 are subscripted"

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
