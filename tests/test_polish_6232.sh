#!/bin/sh
# The steady polish of a slow overshoot (src/run/steady_polish.h): `acbb new
# 6232` (deep groove, 11 050 N radial at 800 rpm, reference profile) has two
# balls at the load zone's edge whose speed and load oscillate from one
# Level-2 pass to the next; the polish ended `diverged` at 3.85e-4 K after
# 100 undamped iterations. It must end converged with the network's heat
# balance closed (MODEL.md 12 item 18: |in - out| <= 1e-6 of the heat in).
# TAP. $1 = the acbb binary.
set -u
ACBB=${1:?usage: test_polish_6232.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-polish-6232.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

"$ACBB" new 6232 --out "$TMP/6232.ini" >/dev/null 2>"$TMP/err"
t $? "acbb new 6232 writes a preset"
"$ACBB" run "$TMP/6232.ini" --json >"$TMP/6232.json" 2>"$TMP/err"
t $? "acbb run 6232 exits 0 ($(head -c 200 "$TMP/err"))"
jqt "$TMP/6232.json" '.status == "converged" and (.message | startswith("thermal steady state"))' \
    "6232 converges: $(jq -r '.status + ": " + .message' "$TMP/6232.json" 2>/dev/null)"
jqt "$TMP/6232.json" '.energy_W.in > 20 and ((.energy_W.in - .energy_W.out) | abs) <= 1e-6 * .energy_W.in' \
    "6232: heat in = heat out within 1e-6 ($(jq -c .energy_W "$TMP/6232.json" 2>/dev/null))"
tap_done
