#!/usr/bin/env bash
# The teaching library: every shipped preset says what it is, what to look
# at and how its run ends ("Expect:"), and its run ends that way.
# $1 = the acbb binary.
. "$(dirname "$0")/tap.sh"
ACBB=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

n_presets=$(ls presets/*.ini | wc -l)
[ "$n_presets" -ge 12 ]
t $? "at least 12 presets ship ($n_presets: 8 teaching scenes and the seed cases)"

"$ACBB" presets >"$TMP/list" 2>&1
for f in presets/*.ini; do
    name=$(basename "$f")
    expect=$(sed -n 's/^; Expect: *\([a-z_]*\).*/\1/p' "$f" | head -n 1)
    grep -q '^; Look at:' "$f" && [ -n "$expect" ]
    t $? "$name: has a 'Look at:' paragraph and an 'Expect:' status ($expect)"
    grep -A6 -x "  $name" "$TMP/list" | grep -q 'look at:'
    t $? "$name: acbb presets shows what to look at"
    start=$(date +%s%N)
    "$ACBB" run "$f" --json >"$TMP/$(basename "$f" .ini).json" 2>/dev/null
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    got=$(jq -r .status "$TMP/$(basename "$f" .ini).json")
    [ "$got" = "$expect" ]
    t $? "$name: runs to its documented status ($got, want $expect; ${ms} ms)"
done

# Every preset states its physics profile (issue 25): the seed paper's
# for the seed presets (7008C and the TE/WTE pair the study and report
# use) and for the runaway scene (its branch needs the seed's stationary
# contact spots: under reference it converges, README "Physics profiles"),
# the reference for the rest; the run JSON says which was used.
for f in presets/*.ini; do
    name=$(basename "$f" .ini)
    case $name in 7008C|te-wte-heavy|te-wte-light|runaway-rigid-preload) want=seed ;;
        *) want=reference ;; esac
    sed -n '/^\[physics\]/,/^\[/p' "$f" | grep -qx "profile = $want" &&
        [ "$(jq -r .profile "$TMP/$name.json")" = "$want" ]
    t $? "$name: states physics.profile = $want, and its run JSON says so"
done

# The scenes say true things: a few of their stated numbers, checked.
"$ACBB" run presets/hertz-contact.ini --json >"$TMP/h.json" 2>/dev/null
jq -e '((.balls[0].Qi_N - 153.5) | if . < 0 then -. else . end) < 0.1
    and .balls[0].pmax_i_GPa > .balls[0].pmax_o_GPa' "$TMP/h.json" >/dev/null
t $? "hertz-contact: Q = Fx / (Z sin alpha) = 153.5 N, inner pmax above outer"
"$ACBB" run presets/angle-split.ini --json >"$TMP/a.json" 2>/dev/null
jq -e '.balls[0].alpha_i_deg > .balls[0].alpha_o_deg + 5' "$TMP/a.json" >/dev/null
t $? "angle-split: alpha_i exceeds alpha_o by more than 5 deg at 16 000 rpm"
"$ACBB" run presets/warm-shaft.ini --json >"$TMP/w.json" 2>/dev/null
"$ACBB" run presets/warm-shaft.ini --set effects.thermal_expansion=off --json >"$TMP/ww.json" 2>/dev/null
jq -e --slurpfile w "$TMP/ww.json" '.squeeze_um.net > 0 and .balls[0].Qi_N > $w[0].balls[0].Qi_N' \
    "$TMP/w.json" >/dev/null
t $? "warm-shaft: the net squeeze is positive and TE raises Qi over WTE"
"$ACBB" run presets/te-wte-heavy.ini --json >"$TMP/hv.json" 2>/dev/null
jq -e '.squeeze_um.net < 0' "$TMP/hv.json" >/dev/null
t $? "te-wte-heavy: the net squeeze is negative (TE loosens at the seed's boundaries)"
# A title is the header's whole first paragraph (issue 29 item 7): cut at
# its first line, the rigid and the spring pair read the same.
"$ACBB" presets 2>/dev/null | tr -s ' \n' '  ' >"$TMP/presets.txt"
grep -q "pair-rigid-16k.ini The same DB pair .* held by rigid spacers (mounting.preload = displacement)" \
    "$TMP/presets.txt" &&
    grep -q "pair-spring-16k.ini The same DB pair .* held by a spring on the floating side" "$TMP/presets.txt"
t $? "acbb presets: the rigid and spring pairs' titles run to the end of their first paragraph"

# The README's preset table (issue 28 item 13: rows had drifted out of it)
# names every preset, in one table: its rows are consecutive.
awk '/^\| preset \| shows \|$/ { on = 1; next } on && /^\|/ { print; next } on { exit }' README.md \
    >"$TMP/table"
miss=""
for p in presets/*.ini; do grep -q -F "\`$(basename "$p")\`" "$TMP/table" || miss="$miss $(basename "$p")"; done
[ -z "$miss" ] && [ "$(grep -c '^| `[a-zA-Z0-9-]*\.ini`' README.md)" -eq "$(grep -c '^| `' "$TMP/table")" ]
t $? "the README's preset table lists every preset, no row outside it${miss:+ (missing:$miss)}"

tap_done
