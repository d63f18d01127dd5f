#!/bin/sh
# The rating life and the preload window from the command line (issue 19):
# the JSON names others script against, `acbb metrics`, the summary, the
# TE/WTE table's life column, and `acbb preload-map` (CSV columns, named
# statuses, no NaN, refusals, the chart). TAP. $1 = the acbb binary; cwd =
# repository root.
set -u
ACBB=${1:?usage: test_life_cli.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-life-cli.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

# ---- the life object (names of the issue) ----
"$ACBB" run presets/combined-load.ini --json >"$TMP/run.json" 2>/dev/null
code $? 0 "combined-load runs"
jq -e '.life | (.C_N > 0) and (.C0_N > 0) and (.L10r_h > 0) and (.Lnmr_h > 0) and (.a_iso > 0)
       and (.kappa > 0) and (.s0_min > 0) and (.edge_loaded | type == "boolean")
       and (.estimated == false) and (.s0_contact | test("^(inner|outer) ball [0-9]+$"))' \
    "$TMP/run.json" >/dev/null
t $? "life: C_N C0_N L10r_h Lnmr_h a_iso kappa s0_min edge_loaded (bool), the worst contact named"
jq -e '(.life.L10r_h - .life.L10r_Mrev * 1e6 / (60 * .scene.keys["operating.inner_speed_rpm"])) | fabs < 1e-6 * 1e9' \
    "$TMP/run.json" >/dev/null
t $? "L10r_h is L10r_Mrev at the scene's speed"
"$ACBB" metrics >"$TMP/metrics"
grep -q '^life\.Lnmr_h  *h ' "$TMP/metrics" && grep -q '^life\.s0_min ' "$TMP/metrics"
t $? "acbb metrics lists life.Lnmr_h (h) and life.s0_min"
"$ACBB" run presets/combined-load.ini >"$TMP/summary" 2>/dev/null
grep -q '^life  *C [0-9.]* kN, C0 ' "$TMP/summary" && grep -q 'L10r .* h, Lnmr ' "$TMP/summary"
t $? "the text summary has the life lines"
"$ACBB" run presets/combined-load.ini --set life.inner_shoulder_mm=0.3 --json \
    >"$TMP/edge.json" 2>"$TMP/err"
jq -e '.life.edge_loaded == true and .life.edge_margin_deg < 0' "$TMP/edge.json" >/dev/null
t $? "a 0.3 mm inner shoulder: edge_loaded"
grep -q '^acbb: warning: edge loading: the contact ellipse of inner ball [0-9]* passes its shoulder' \
    "$TMP/err"
t $? "  and a named warning on stderr"
# ---- issue 25: C0, C_u, s0 on one basis; a_ISO below kappa 0.1 said ----
jq -e '.life | .C0_basis == "4200 MPa, real grooves" and (.C0_N / .P0_N / .s0_min - 1 | fabs < 1e-9)
       and (.Cu_N * 22 / .C0_N - 1 | fabs < 1e-12) and .kappa_clamped == false' \
    "$TMP/run.json" >/dev/null
t $? "combined-load (grooves 0.5402): C0 from 4200 MPa, C0 / P0_N = s0_min, C_u = C0 / 22"
"$ACBB" run presets/deep-groove-radial.ini --json 2>/dev/null |
    jq -e '.life.C0_basis == "ISO 76 Table 1"' >/dev/null
t $? "deep-groove-radial (grooves 0.52 / 0.53 D_w): C0 from ISO 76 Table 1"
grep -q 'kN, C0 [0-9.]* kN (4200 MPa, real grooves)' "$TMP/summary" &&
    grep -q 's0 [0-9.]* (.*), P0 [0-9.]* N (static equivalent load)$' "$TMP/summary"
t $? "the text summary names C0's basis and P0"
"$ACBB" run presets/7008C.ini --set operating.inner_speed_rpm=10 --json >"$TMP/slow.json" \
    2>"$TMP/err"
jq -e '.life.kappa < 0.1 and .life.kappa_clamped == true' "$TMP/slow.json" >/dev/null
t $? "10 rpm: kappa < 0.1, life.kappa_clamped true"
grep -q '^acbb: warning: kappa 0.0[0-9]* is below 0.1, where ISO 281 does not define a_ISO' "$TMP/err"
t $? "  and a warning on stderr"
"$ACBB" run presets/7008C.ini --set operating.inner_speed_rpm=10 2>/dev/null |
    grep -q 'kappa below 0.1, where ISO 281 has no a_ISO: a_ISO taken at 0.1$'
t $? "  and in the text summary"
"$ACBB" run presets/combined-load.ini --set life.reliability_pct=80 >/dev/null 2>"$TMP/err"
code $? 2 "reliability 80 % refused"
has "$TMP/err" "life.reliability_pct" "  the message names the key"

# ---- preload-map ----
# The seed's physics: its stationary contact spots let the heavy preload run
# away at speed (moving-source contact heat, the reference profile's, would
# not; README "Physics profiles").
"$ACBB" preload-map presets/preload-window.ini --speeds 8000:24000:3 --preloads 1:601:3 \
    --max-rise 20 --set physics.profile=seed --csv "$TMP/map.csv" >"$TMP/map.txt" 2>"$TMP/err"
code $? 0 "preload-map runs"
head -n 1 "$TMP/map.csv" | grep -q -x 'operating.inner_speed_rpm,mounting.preload_N,status,verdict,skid_ratio,temp_rise_K,life.Lnmr_h,life.s0_min'
t $? "CSV columns: the scene keys, status, verdict and the limits' values as acbb metrics names them (issue 28 item 7)"
awk -F, 'NR > 1 && $7 != "" { n = $7; gsub(/[-.]|e.*/, "", n); sub(/^0+/, "", n); if (length(n) > 10) long = 1 } END { exit !long }' "$TMP/map.csv"
t $? "CSV numbers carry 17 significant digits (more than 10)"
"$ACBB" preload-map presets/preload-window.ini --speeds 8000:24000:3 --preloads 1:601:3 \
    --max-rise 20 --set physics.profile=seed --json >"$TMP/map.json" 2>"$TMP/err"
code $? 0 "preload-map --json runs"
python3 - "$TMP/map.json" "$TMP/map.csv" <<'PY'
import csv, json, sys
d = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
cells = d["preload_map"]["cells"]
assert d["schema_version"] >= 4 and len(cells) == len(rows) == 9 and len(d["preload_map"]["rows"]) == 3
for c, r in zip(cells, rows):
    assert list(c) == list(r), (list(c), list(r))
    for k, v in c.items():
        assert (v == float(r[k]) if isinstance(v, float) or isinstance(v, int) else
                (v is None and r[k] == "") or v == r[k]), (k, v, r[k])
assert d["preload_map"]["limits"]["max_rise_K"] == 20 and d["preload_map"]["limits"]["min_s0"] is None
PY
t $? "--json: the CSV's cells (same names, the same doubles), each speed's row and the limits"
"$ACBB" preload-map presets/7008C.ini --speeds 4000:4000:1 --preloads 100:100:1 --json --csv - >/dev/null 2>"$TMP/err"
code $? 2 "--json with --csv - (one stdout) refused"
[ "$(($(wc -l <"$TMP/map.csv") - 1))" -eq 9 ]; t $? "one row per cell (3 x 3)"
awk -F, 'NR > 1 && ($3 !~ /^(converged|runaway|not_converged|diverged|contact_lost|nonfinite|cancelled|[a-z_]+)$/ ||
    $4 !~ /^(ok|skid|hot|short_life|low_s0|runaway|failed)$/) { bad = 1 } END { exit bad }' "$TMP/map.csv"
t $? "every cell has a named status and verdict"
grep -qi 'nan\|inf' "$TMP/map.csv"; [ $? -ne 0 ]; t $? "no NaN or Inf in the CSV"
grep -q ',runaway,runaway,' "$TMP/map.csv"; t $? "the heavy preload at speed runs away (named)"
grep -q '^ *24000 .*none$\|^ *24000 .* [0-9.]* \.\. [0-9.]*$' "$TMP/map.txt"
t $? "the table gives the window per speed"
"$ACBB" preload-map presets/7008C.ini --speeds 100:50:2 --preloads 1:2:2 >/dev/null 2>"$TMP/err"
code $? 2 "speeds high below low refused"
has "$TMP/err" "need 0 < low <= high" "  with the reason"
"$ACBB" preload-map presets/7008C.ini --speeds 4000:8000 --preloads 1:2:2 >/dev/null 2>"$TMP/err"
code $? 2 "--speeds without N refused"
has "$TMP/err" "LO:HI:N" "  the message shows the form"
"$ACBB" preload-map presets/7008C.ini --speeds 4000:8000:2 >/dev/null 2>"$TMP/err"
code $? 2 "--preloads missing refused"
"$ACBB" preload-map presets/7008C.ini --speeds 4000:8000:2 --preloads 1:2:2 --plot "$TMP/x.pdf" \
    >/dev/null 2>"$TMP/err"
code $? 2 "--plot FILE.pdf refused"
if command -v gnuplot >/dev/null 2>&1; then
    "$ACBB" preload-map presets/7008C.ini --speeds 4000:8000:2 --preloads 50:100:2 \
        --plot "$TMP/w.svg" >/dev/null 2>"$TMP/err"
    code $? 0 "--plot FILE.svg"
    grep -q 'Preload window' "$TMP/w.svg"; t $? "  the chart is written"
    # issue 29 item 9: a window reaching the grid's last preload found no
    # limit there; the chart must not draw that end as the upper limit.
    printf '#!/bin/sh\ntee "%s/w.gp" | gnuplot\n' "$TMP" >"$TMP/gpw"
    chmod +x "$TMP/gpw"
    # (The seed's physics, as the map above: 24 000 rpm meets a limit.)
    ACBB_GNUPLOT="$TMP/gpw" "$ACBB" preload-map presets/preload-window.ini --speeds 8000:24000:3 \
        --preloads 1:601:3 --set physics.profile=seed --plot "$TMP/w2.svg" >"$TMP/w2.txt" 2>"$TMP/err"
    code $? 0 "--plot of a window that reaches the grid's top at 8000 and 16000 rpm"
    grep -q '^ *8000 .* 1 \.\. 601$' "$TMP/w2.txt"; t $? "  (the table: 1 .. 601 N at 8000 rpm)"
    # $S1: the upper limits found; $S3: the grid's top where no limit was met
    awk '/^\$S1 << EOD/ { b = 1; next } /^\$S3 << EOD/ { b = 3; next } /^EOD/ { b = 0 }
         b == 1 && $2 == 601 { bad = 1 } b == 3 && $2 == 601 { top++ }
         END { exit bad || top != 2 }' "$TMP/w.gp"
    t $? "  601 N (the grid's top) is drawn as 'grid top, no limit', never as the upper limit"
    grep -q "set xlabel 'inner-ring speed (rpm)'" "$TMP/w.gp" && grep -q "set ylabel 'preload (N)'" "$TMP/w.gp"
    t $? "  axis labels are words with units"
else
    skip "--plot FILE.svg" "gnuplot not installed"
fi
tap_done
