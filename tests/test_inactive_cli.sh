#!/bin/sh
# An edit that does nothing says so (issue 29 item 1): `acbb check` and
# `acbb run` name a single bearing's preload_N under a force preload and its
# axial load under a displacement preload, with the key that makes each act,
# and the run JSON lists them in effects_inactive; a DB pair uses both and
# says nothing. TAP. $1 = acbb; cwd = repository root.
set -u
ACBB=${1:?usage: test_inactive_cli.sh path/to/acbb}
case $ACBB in /*) ;; *) ACBB=$PWD/$ACBB ;; esac
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-inactive.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

"$ACBB" check presets/7008C.ini --set mounting.preload_N=600 >/dev/null 2>"$TMP/err"
code $? 0 "check: a preload_N edit under a force preload is valid"
has "$TMP/err" "mounting.preload_N has no effect here: mounting.preload = force" \
    "check says preload_N has no effect under a force preload"
has "$TMP/err" "preload_N acts under mounting.preload = displacement" "  and names what makes it act"
"$ACBB" check presets/7008C.ini --set mounting.preload=displacement >/dev/null 2>"$TMP/err"
has "$TMP/err" "operating.axial_load_N has no effect here: mounting.preload = displacement" \
    "check says the axial load has no effect under a displacement preload"
"$ACBB" run presets/7008C.ini --set mounting.preload=displacement --set effects.heating=off \
    --json >"$TMP/run.json" 2>/dev/null
jqt "$TMP/run.json" '[.effects_inactive[].key] | index("operating.axial_load_N") != null' \
    "run JSON: effects_inactive names operating.axial_load_N"
"$ACBB" check presets/pair-DB-heated.ini >/dev/null 2>"$TMP/err"
! grep -q 'has no effect here' "$TMP/err"
t $? "a DB pair under displacement preload: no note (the set uses both)"
"$ACBB" check presets/7008C.ini >/dev/null 2>"$TMP/err"
! grep -q 'has no effect here' "$TMP/err"
t $? "7008C as shipped: no note"
tap_done
