#!/usr/bin/env bash
# python/acbb.py (ctypes + json) against the build's libacbb.so: 7008C run
# from Python, by path and as text with settings, equals `acbb run --json`
# (every key but wall_ms); the library is found through lib=, ACBB_LIB and
# beside the module; bad input raises AcbbError with the engine's message.
# $1 acbb, $2 the build's libacbb.so, $3 b_sanitize, $4 the C compiler (a
# sanitized library needs its runtime preloaded into python).
set -u
ACBB=$1 LIB=$2 SAN=${3:-none} CC=${4:-cc}
cd "$(dirname "$0")/.." || exit 1
. tests/tap.sh
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
if ! command -v python3 >/dev/null; then
    echo "1..0 # SKIP no python3"
    exit 0
fi
case "$SAN" in
    *address*)
        export LD_PRELOAD=$("$CC" -print-file-name=libasan.so)
        export ASAN_OPTIONS=detect_leaks=0 ;;   # python's own allocations
esac

"$ACBB" run presets/7008C.ini --json >"$TMP/cli.json" 2>"$TMP/err"
code $? 0 "acbb run presets/7008C.ini --json"
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=300 --set effects.thermal_expansion=off \
    --json >"$TMP/cli_set.json" 2>"$TMP/err"
code $? 0 "acbb run with two --set"

# py SCRIPT: run python with the module on its path; $TMP and $LIB given.
py() { PYTHONPATH=python python3 - "$TMP" "$LIB" 2>"$TMP/err"; }

py <<'PY' >"$TMP/out"
import json, sys
import acbb
tmp, lib = sys.argv[1], sys.argv[2]
def same(doc, ref_path):
    ref = json.load(open(ref_path))
    for d in (doc, ref):
        d.pop("wall_ms")
    return doc == ref and doc["status"] == "converged"
r = acbb.run("presets/7008C.ini", lib=lib)
print("path", same(r, tmp + "/cli.json"))
text = open("presets/7008C.ini").read()
r = acbb.run(text, {"operating.axial_load_N": 300, "effects.thermal_expansion": False}, lib=lib)
print("text", same(r, tmp + "/cli_set.json"))
PY
code $? 0 "python runs 7008C through libacbb"
has "$TMP/out" "path True" "by path: the CLI's JSON, every key but wall_ms"
has "$TMP/out" "text True" "as text with a settings dict: the CLI's JSON with --set"

ACBB_LIB=$LIB py <<'PY' >"$TMP/out"
import acbb
r = acbb.run("presets/7008C.ini", ["operating.inner_speed_rpm=9000"])
print("env", r["scene"]["inner_speed_rpm"])
PY
has "$TMP/out" "env 9000" "ACBB_LIB finds the library; a settings list"

mkdir -p "$TMP/mod" && cp python/acbb.py "$TMP/mod/" && cp "$LIB" "$TMP/mod/libacbb.so.0"
SRC=$PWD
(cd "$TMP/mod" && env -u ACBB_LIB python3 -c '
import acbb, sys
print("beside", acbb.run(sys.argv[1] + "/presets/7008C.ini")["status"])' "$SRC") \
    >"$TMP/out" 2>"$TMP/err"
has "$TMP/out" "beside converged" "libacbb.so.0 beside the module is found"

py <<'PY' >"$TMP/out"
import sys
import acbb
lib = sys.argv[2]
try:
    acbb.run("presets/7008C.ini", {"operating.axial_load_N": -5}, lib=lib)
except acbb.AcbbError as e:
    print("raised", e.status, e.code, "|" + str(e) + "|")
try:
    acbb.run("[operating]\naxial_load_N = abc\n", lib=lib)
except acbb.AcbbError as e:
    print("raised", e.status, "|" + str(e) + "|")
try:
    acbb.load_library(sys.argv[1] + "/no/libacbb.so.0")
except acbb.AcbbError as e:
    print("nolib", str(e))
PY
MSG="operating.axial_load_N=-5: operating.axial_load_N = -5: must be >= 0 N"
has "$TMP/out" "raised bad_input -1 |$MSG|" \
    "a bad setting raises AcbbError with the engine's message"
has "$TMP/out" "raised bad_input |<text>:2: operating.axial_load_N = abc: not a number|" \
    "bad preset text raises AcbbError naming <text>:line"
has "$TMP/out" "nolib cannot find the acbb library" "a missing library is said"

tap_done
