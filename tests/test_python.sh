#!/usr/bin/env bash
# python/acbb.py (ctypes + json) against the build's libacbb.so: 7008C run
# from Python, by path and as text with settings, equals `acbb run --json`
# (every key but wall_ms); the library is found through lib=, ACBB_LIB and
# beside the module; bad input raises AcbbError with the engine's message.
# $1 acbb, $2 the build's libacbb.so, $3 b_sanitize, $4 the C compiler (a
# sanitized library needs its runtime preloaded into python).
# Issue 28 items 1, 2, 4: the FFI's document is the CLI's byte for byte
# on every preset (wall_ms's value aside); a preset by name through the
# CLI's search path; __version__; Ctrl-C cancels a running call; a NUL
# byte in the text is refused; error documents carry schema_version.
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
print("env", r["scene"]["keys"]["operating.inner_speed_rpm"])
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

# Every preset: the FFI's text is `acbb run --json`'s, byte for byte, but
# for wall_ms's value (the run's wall time).
py <<'PY' >"$TMP/ffi.log"
import ctypes, glob, os, sys
lib = ctypes.CDLL(sys.argv[2])
f = lib.acbb_run_preset_json
f.restype, f.argtypes = ctypes.c_void_p, [ctypes.c_char_p, ctypes.c_void_p, ctypes.c_size_t,
                                          ctypes.POINTER(ctypes.c_int)]
for path in sorted(glob.glob("presets/*.ini")):
    code = ctypes.c_int(0)
    p = f(open(path, "rb").read(), None, 0, ctypes.byref(code))
    name = os.path.basename(path)[:-4]
    open(f"{sys.argv[1]}/ffi-{name}.json", "wb").write(ctypes.string_at(p))
    lib.acbb_string_free(ctypes.c_void_p(p))
    print(name)
PY
nw() { sed 's/^\(  "wall_ms": \)[0-9.e+-]*,$/\1W,/' "$1"; }
np=0 bad=""
for ini in presets/*.ini; do
    name=$(basename "$ini" .ini)
    "$ACBB" run "$ini" --json >"$TMP/cli-$name.json" 2>/dev/null
    np=$((np + 1))
    cmp -s <(nw "$TMP/cli-$name.json") <(nw "$TMP/ffi-$name.json") || bad="$bad $name"
done
[ "$np" -ge 19 ] && [ "$(wc -l <"$TMP/ffi.log")" -eq "$np" ] && [ -z "$bad" ] \
    && grep -q '"branches"' "$TMP/ffi-pair-DB-heated.json"
t $? "the FFI's document is acbb run --json's byte for byte on all $np presets (branches included)${bad:+; differ:$bad}"

py <<'PY' >"$TMP/out"
import sys
import acbb
lib = sys.argv[2]
print("version", acbb.__version__)
r = acbb.run("7008C", lib=lib)
print("byname", r["status"], r["scene"]["keys"]["operating.inner_speed_rpm"])
try:
    acbb.run("[operating]\naxial_load_N = 100\0 junk\n", lib=lib)
    print("nul ran")
except acbb.AcbbError as e:
    print("nul", e.status, "|" + str(e) + "|", e.result["schema_version"])
try:
    acbb.run("7008C", ["operating.axial_load_N=-5"], lib=lib)
except acbb.AcbbError as e:
    print("refusal schema_version", e.result.get("schema_version"))
try:
    acbb.run("no-such-preset", lib=lib)
except acbb.AcbbError as e:
    print("missing", e.status, str(e).split(":")[0])
PY
has "$TMP/out" "version $("$ACBB" --version | awk '{ print $2 }')" "acbb.__version__ is acbb --version's"
has "$TMP/out" "byname converged 15000" "a preset by name (7008C) is found as the CLI finds it"
has "$TMP/out" "nul bad_input |<text>:2: NUL byte in line 2 (a preset is plain text)| 4" \
    "a NUL byte in the text is refused with the CLI's message (it used to cut the text and run)"
has "$TMP/out" "refusal schema_version 4" "a bad_input document carries schema_version"
has "$TMP/out" "missing bad_input cannot open preset no-such-preset" "an unknown name is said"

# An ill-posed scene: the CLI's status and message (bad_input, exit 2).
"$ACBB" run presets/7008C.ini --set operating.axial_load_N=0 --set operating.radial_load_N=500 \
    --json 2>/dev/null | jq -r '"\(.status) \(.message)"' >"$TMP/ill_cli"
py <<'PY' >"$TMP/ill_py"
import sys
import acbb
try:
    acbb.run("7008C", {"operating.axial_load_N": 0, "operating.radial_load_N": 500}, lib=sys.argv[2])
except acbb.AcbbError as e:
    print(e.status, e)
PY
[ -s "$TMP/ill_cli" ] && cmp -s "$TMP/ill_cli" "$TMP/ill_py" && grep -q "^bad_input " "$TMP/ill_py"
t $? "an ill-posed scene: the same status and message as the CLI's ($(cat "$TMP/ill_py"))"

# Ctrl-C during a long call: SIGINT once python runs the call in its
# worker thread (python catches SIGINT and a second thread is in /proc),
# then acbb.Cancelled (a KeyboardInterrupt) with the library's "cancelled"
# document. It used to come only when the run had finished, as a plain
# KeyboardInterrupt. The call is tests/unending.ini (the dynamic level on a
# schedule that cannot settle before millions of steps), so it is still
# running when the signal comes on any machine: combined-load itself ends
# in about a second, and a fast machine could print "finished converged".
PYTHONPATH=python python3 - "$LIB" >"$TMP/out" 2>"$TMP/err" <<'PY' &
import signal, sys
# A background job starts with SIGINT ignored; Python's own handler back.
signal.signal(signal.SIGINT, signal.default_int_handler)
import acbb
try:
    r = acbb.run("tests/unending.ini", lib=sys.argv[1])
    print("finished", r["status"])
except acbb.Cancelled as e:
    print("cancelled", isinstance(e, KeyboardInterrupt), e.result["status"],
          e.result["schema_version"])
PY
pid=$!
for ((i = 0; i < 600; i++)); do
    m=$(awk '/^SigCgt:/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
    [ -n "$m" ] && (( (16#$m & 0x2) == 0x2 )) \
        && [ "$(ls "/proc/$pid/task" 2>/dev/null | wc -l)" -ge 2 ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.1
done
kill -INT $pid
# (the call cannot end by itself: a signal that did nothing must not hang
# the test; 60 s only turns that into a failure)
for ((i = 0; i < 600; i++)); do
    kill -0 $pid 2>/dev/null && [ "$(awk '{ print $3 }' "/proc/$pid/stat" 2>/dev/null)" != Z ] || break
    sleep 0.1
done
kill -KILL $pid 2>/dev/null
wait $pid
has "$TMP/out" "cancelled True cancelled 4" \
    "SIGINT stops a running call: acbb.Cancelled, a KeyboardInterrupt, with the cancelled document"

tap_done
