#!/bin/sh
# A nonzero exit says why on stderr, in one line naming the command and
# the cause: the batch commands (study, report, sweep, bench) exited 3
# when runs failed without a word on stderr; `bench speed` listed the
# runs it had not run as "ok" failures; `bench accuracy --envelope`
# printed nan for settings that converged at no point.
# The runs fail by thermal.max_steps = 2 (no steady state in 2 steps).
# $1 = the acbb binary; cwd = repository root. TAP.
set -u
ACBB=${1:?usage: test_exit_why.sh path/to/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-why.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

P=presets/7008C.ini
Q="--set fidelity.model=quasi-static"
F="--set thermal.max_steps=2"
WHY="no steady state within the limits (2 steps"

# one CMD TEXT: exactly one line of stderr starts "acbb: CMD: ", and it
# holds TEXT.
one() {
    [ "$(grep -c "^acbb: $1: " "$TMP/err")" -eq 1 ] && grep "^acbb: $1: " "$TMP/err" | grep -qF -- "$2"
    t $? "... one line on stderr: acbb: $1: ...$2..."
    [ "$(grep -c "^acbb: $1: " "$TMP/err")" -eq 1 ] || sed 's/^/# /' "$TMP/err" | head -5
}

# shellcheck disable=SC2086
"$ACBB" study $P $Q $F >"$TMP/out" 2>"$TMP/err"
code $? 3 "study with failing runs"
one study "48 of 48 runs failed (first: TE at Fx N 50: not_converged: $WHY"

# shellcheck disable=SC2086
"$ACBB" study $P $Q $F --out "$TMP/fig" >"$TMP/out" 2>"$TMP/err"
code $? 3 "study --out with failing runs"
grep -q "^acbb: study: 101 of 101 runs failed (first: .*: not_converged: $WHY" "$TMP/err" &&
    grep -q ", 101 failed;" "$TMP/fig/REPORT.md"
t $? "... says the failed runs that REPORT.md counts"

# shellcheck disable=SC2086
"$ACBB" report $P $Q $F >"$TMP/out" 2>"$TMP/err"
code $? 3 "report with failing runs"
one report "101 of 101 runs failed (first: 15000 rpm, 50 N, TE, quasi-dynamic: not_converged: $WHY"
# shellcheck disable=SC2086
"$ACBB" report $P $Q $F --json >"$TMP/out" 2>"$TMP/err"
code $? 3 "report --json with failing runs"
one report "101 of 101 runs failed (first: "
jq -e 'type == "array"' "$TMP/out" >/dev/null 2>&1
t $? "... stdout is still the JSON report"

# Streaming, one point of two failing: the lowest failed index is named.
# shellcheck disable=SC2086
"$ACBB" sweep $P $Q --grid thermal.max_steps=20000,2 --grid operating.axial_load_N=100,200 \
    --jsonl "$TMP/s.jsonl" >"$TMP/out" 2>"$TMP/err"
code $? 3 "sweep --jsonl with two of four points failing"
one sweep "2 of 4 runs failed (first: thermal.max_steps=2, operating.axial_load_N=100: not_converged: $WHY"
# The 1-D table and its JSON.
# shellcheck disable=SC2086
"$ACBB" sweep $P $Q $F --param operating.axial_load_N --values 300,100,200 >"$TMP/out" 2>"$TMP/err"
code $? 3 "sweep --param with every point failing"
one sweep "3 of 3 runs failed (first: operating.axial_load_N=300: not_converged: $WHY"
has "$TMP/err" "the table lists them" "... and says the table lists them"
# shellcheck disable=SC2086
"$ACBB" sweep $P $Q $F --param operating.axial_load_N --values 100,200 --json >"$TMP/out" 2>"$TMP/err"
code $? 3 "sweep --param --json with every point failing"
one sweep "2 of 2 runs failed (first: operating.axial_load_N=100: not_converged: "

# bench speed: only the run that failed is listed; the seven sweep points
# it never ran were listed as "run 1: ok:" and so on.
# shellcheck disable=SC2086
"$ACBB" bench speed $P $Q $F --repeat 1 >"$TMP/out" 2>"$TMP/err"
code $? 3 "bench speed with a failing run"
[ "$(grep -c '^acbb: ' "$TMP/err")" -eq 1 ] && ! grep -q ': ok:' "$TMP/err"
t $? "... one line, no run listed as ok"
one "bench speed" "run 0: not_converged: $WHY"
! grep -q '^one run' "$TMP/out"
t $? "... and no time printed for the failed run"

# shellcheck disable=SC2086
"$ACBB" bench accuracy $P $Q $F --repeat 1 --knobs contact_grid >"$TMP/out" 2>"$TMP/err"
code $? 3 "bench accuracy with failing settings"
one "bench accuracy" "9 of 9 runs failed (first: contact_grid=4: not_converged: $WHY"
# shellcheck disable=SC2086
"$ACBB" bench accuracy $P $Q $F --envelope --points 2 --knobs contact_grid \
    >"$TMP/out" 2>"$TMP/err"
code $? 3 "bench accuracy --envelope with failing settings"
one "bench accuracy --envelope" "16 of 16 settings did not converge with their reference at every point (first: contact_grid=4, 0 of 2)"
! grep -qi 'nan' "$TMP/out" && grep -q '^contact_grid=4 .* 0/2 .* -  *-$' "$TMP/out" &&
    grep -qF '/* reference */ not measured: converged at 0 of 2 points' "$TMP/out"
t $? "... no nan on stdout: '-' for work and ms, no stored row"

tap_done
