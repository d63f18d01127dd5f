#!/usr/bin/env bash
# The engine as a library (issue 16, README "The engine as a library"):
# `meson install --destdir` holds libacbb.so (and its soname links),
# libacbb.a, the public headers (no internal one) and acbb.pc; the shared
# library exports the public API only; examples/run_preset.c builds with
# `pkg-config --cflags --libs acbb` against that DESTDIR, shared (run with
# LD_LIBRARY_PATH) and fully static (`--static`), and prints what
# `acbb run --json` says for 7008C.
# $1 acbb, $2 the build directory, $3 its b_sanitize ("none", or e.g.
# "address,undefined": the example then needs the same -fsanitize), $4 the
# build's C compiler, $5 the python3 meson found (the module's site
# directory is chosen for it).
set -u
ACBB=$1 BUILD=$2 SAN=${3:-none} CC=${4:-cc} PY=${5:-python3}
cd "$(dirname "$0")/.." || exit 1
. tests/tap.sh
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
D=$TMP/d

# Two tests install from the same build directory (test_cli, test_install_lib):
# one at a time (both write the build's meson-logs/install-log.txt).
flock "$BUILD/meson-private/acbb-test-install.lock" \
    meson install -C "$BUILD" --destdir "$D" --no-rebuild --quiet >"$TMP/inst.log" 2>"$TMP/err"
code $? 0 "meson install --destdir"
# meson prints its ERROR lines on stdout
grep -h -s ERROR "$TMP/inst.log" "$TMP/err" | sed 's/^/# /' | head -n 20
PC=$(find "$D" -name acbb.pc -path '*/pkgconfig/*' | head -n 1)
[ -n "$PC" ]
t $? "acbb.pc is installed (${PC#"$D"})"
LIB=$(dirname "$(dirname "$PC")")
[ -f "$LIB/libacbb.a" ]
t $? "libacbb.a is installed beside it"
[ -L "$LIB/libacbb.so" ] && [ -L "$LIB/libacbb.so.0" ] \
    && [ -f "$(readlink -f "$LIB/libacbb.so")" ] && readelf -d "$LIB/libacbb.so" | grep -q 'SONAME.*\[libacbb\.so\.0\]'
t $? "libacbb.so is installed, a link to the file of soname libacbb.so.0"
INC=$(find "$D" -type d -path '*/include/acbb' | head -n 1)
diff <(cd include/acbb && ls -- *.h) <(cd "$INC" && ls) >"$TMP/err"
t $? "the installed headers are exactly include/acbb/*.h, the core (${INC#"$D"})"
[ -z "$(find "$D" -path '*/acbb/tools*' -o -name study.h -o -name json.h)" ]
t $? "no tools header (include/acbb/tools/: study.h, json.h, ...) is installed"
[ -f "$INC/acbb.h" ] && [ -f "$INC/ffi.h" ] \
    && [ -z "$(find "$D" -name hertz.h -o -name scene_internal.h)" ]
t $? "acbb.h and ffi.h are there, no internal header (hertz.h, scene_internal.h)"

# The shared library's dynamic symbols are the public API: each is named in
# an installed header, and an internal (acbb_sf_parse) is not among them.
nm -D --defined-only "$LIB/libacbb.so" | awk '$2 ~ /^[TDBR]$/ { print $3 }' | sort -u >"$TMP/syms"
bad=""
while read -r s; do grep -q -w -- "$s" "$INC"/*.h || bad="$bad $s"; done <"$TMP/syms"
nsyms=$(wc -l <"$TMP/syms")
[ "$nsyms" -gt 40 ] && [ -z "$bad" ] && grep -q -x acbb_run_preset_json "$TMP/syms" \
    && grep -q -x acbb_sim_create "$TMP/syms"
t $? "libacbb.so exports $nsyms symbols, all named in the public headers${bad:+ (not:$bad)}"
! grep -q -x -e acbb_sf_parse -e acbb_sf_find "$TMP/syms"
t $? "internals (acbb_sf_parse, acbb_sf_find) are not exported"
# The tools serve the CLI and the TUI (static library): none is exported,
# and the one constructor is acbb_sim_create (issue 27 item 5).
! grep -q -x -e acbb_study_run -e acbb_json_num -e acbb_out_open -e acbb_sim_new \
    -e acbb_sim_new_ctl "$TMP/syms"
t $? "tools (acbb_study_run, acbb_json_num, acbb_out_open) and the old constructors are not exported"
# The core is what a program that loads, edits by key, validates, runs and
# reads scenes needs (issue 27 item 5: about 45 functions): the editors'
# key table, inactive keys, comment-keeping writer, the lubricant helpers
# and the surroundings are tools (acbb/tools/scene_schema.h, ...).
! grep -q -x -e acbb_scene_field -e acbb_scene_field_count -e acbb_scene_key_inactive \
    -e acbb_scene_save_edits -e acbb_scene_write -e acbb_lubricant_apply \
    -e acbb_scene_surroundings -e acbb_model_level_name "$TMP/syms"
t $? "the editors' scene functions (acbb_scene_field, acbb_scene_save_edits, ...) are not exported"
[ "$nsyms" -le 45 ] && grep -q -x -e acbb_scene_apply_edits "$TMP/syms" \
    && grep -q -x -e acbb_output_find "$TMP/syms"
t $? "libacbb.so exports at most 45 functions ($nsyms), acbb_scene_apply_edits and acbb_output_find among them"

export PKG_CONFIG_PATH="$(dirname "$PC")" PKG_CONFIG_SYSROOT_DIR="$D"
pkg-config --cflags acbb | grep -q -F -- "-I$D/"
t $? "pkg-config --cflags acbb points into the DESTDIR"
SANF=()
[ "$SAN" != none ] && SANF=("-fsanitize=$SAN")
# shellcheck disable=SC2046  # pkg-config's words are meant to split
EX=$(find "$D" -path '*/doc/acbb/examples/run_preset.c' | head -n 1)
[ -n "$EX" ] && cmp -s "$EX" examples/run_preset.c
t $? "the example is installed (${EX#"$D"})"
"$CC" "${SANF[@]}" "${EX:-examples/run_preset.c}" $(pkg-config --cflags --libs acbb) -o "$TMP/ex" \
    2>"$TMP/err"
code $? 0 "the installed example builds with pkg-config --cflags --libs acbb"
# The installed headers from C++ (issue 28 item 5): extern "C", no C11
# _Atomic in a public type.
if command -v c++ >/dev/null; then
    printf '#include <acbb/acbb.h>\nint main() { acbb_scene s; acbb_scene_default(&s); return s.heating ? 0 : 1; }\n' >"$TMP/cxx.cpp"
    # shellcheck disable=SC2046
    c++ -std=c++17 -Wall -Wextra -Werror -pedantic -fsyntax-only $(pkg-config --cflags acbb) \
        "$TMP/cxx.cpp" 2>"$TMP/err"
    code $? 0 "the installed <acbb/acbb.h> compiles as C++17"
else
    skip "the installed <acbb/acbb.h> compiles as C++17" "no C++ compiler"
fi
LD_LIBRARY_PATH=$LIB ldd "$TMP/ex" | grep -q -F "libacbb.so.0 => $LIB/"
t $? "it links libacbb.so.0 from the DESTDIR"
LD_LIBRARY_PATH=$LIB "$TMP/ex" presets/7008C.ini >"$TMP/ex.txt" 2>"$TMP/err"
code $? 0 "the example runs 7008C to convergence (exit 0)"

"$ACBB" run presets/7008C.ini --json >"$TMP/run.json" 2>"$TMP/err"
code $? 0 "acbb run presets/7008C.ini --json"
# The example prints %.17g, as the JSON does: the same numbers exactly.
val() { awk -v k="$1" '$1 == k { print $2 }' "$TMP/ex.txt"; }
jq -e --arg st "$(val status)" --argjson T "$(val temperature_C.outer_ring)" \
    --argjson P "$(val losses_W.total)" --argjson Q "$(val 'balls[0].Qi_N')" \
    '.status == $st and $st == "converged" and .temperature_C.outer_ring == $T
     and .losses_W.total == $P and .balls[0].Qi_N == $Q' "$TMP/run.json" >/dev/null 2>&1
t $? "status, outer-ring temperature, total loss and Qi, named by their JSON paths, equal the CLI's JSON"

if [ "$SAN" = none ]; then
    # shellcheck disable=SC2046
    "$CC" -static examples/run_preset.c $(pkg-config --cflags --libs --static acbb) \
        -o "$TMP/ex_static" 2>"$TMP/err"
    code $? 0 "the example links fully static with pkg-config --libs --static acbb"
    ! readelf -d "$TMP/ex_static" 2>/dev/null | grep -q NEEDED
    t $? "the static example needs no shared library"
    "$TMP/ex_static" presets/7008C.ini >"$TMP/exs.txt" 2>"$TMP/err"
    code $? 0 "the static example runs 7008C (exit 0)"
    cmp -s "$TMP/ex.txt" "$TMP/exs.txt"
    t $? "static and shared print the same"
else
    skip "the example links fully static" "sanitizer build ($SAN): no static runtime"
fi
# The Python module as installed (issue 28 item 1): in the Python site
# directory, where `import acbb` works with PYTHONPATH at the DESTDIR's
# site directory only (nothing under share/); it has __version__, finds the
# library of its own prefix and the installed presets by name, as the CLI
# does, from a directory with no presets/ and no user presets.
PYMOD=$(find "$D" -name acbb.py -path '*-packages/acbb.py' | head -n 1)
[ -n "$PYMOD" ] && [ -z "$(find "$D" -path '*/share/acbb/python*')" ]
t $? "acbb.py is installed into the Python site directory (${PYMOD#"$D"}), not share/acbb/python"
# ... and that directory (less the DESTDIR) is one the configured python3
# searches without PYTHONPATH: in its sys.path, or in its site module's
# list of site directories (which counts one not created yet). meson's own
# choice for prefix /usr/local was searched by no interpreter under pyenv
# (/usr/local/lib/python3.X/site-packages) nor under Debian's python3
# (/usr/local/lib/python3/dist-packages); python/site_dir.py chooses.
PYDIR=$(dirname "${PYMOD#"$D"}")
env -u PYTHONPATH "$PY" -c 'import os, site, sys
d = sys.path + site.getsitepackages() + ([site.getusersitepackages()] if site.ENABLE_USER_SITE else [])
sys.exit(os.path.normpath(sys.argv[1]) not in [os.path.normpath(x) for x in d if x])' "$PYDIR"
t $? "the configured $PY searches $PYDIR without PYTHONPATH"
# site_dir.py's three rules on the site lists of Debian's python3, pyenv's
# and a venv (any machine): meson's directory when searched, else one under
# the prefix, else the interpreter's own.
PYTHONPATH=python "$PY" - >"$TMP/site.txt" 2>&1 <<'PY'
from site_dir import choose
deb = ["/usr/local/lib/python3.11/dist-packages", "/usr/lib/python3/dist-packages",
       "/usr/lib/python3.11/dist-packages", "/root/.local/lib/python3.11/site-packages"]
pyenv = ["/h/.pyenv/versions/3.11.7/lib/python3.11/site-packages",
         "/h/.local/lib/python3.11/site-packages"]
venv = ["/h/venv/lib/python3.11/site-packages"]
cases = [
    ("/usr", "/usr/lib/python3/dist-packages/", deb, "/usr/lib/python3/dist-packages"),
    ("/usr/local", "/usr/local/lib/python3/dist-packages/", deb,
     "/usr/local/lib/python3.11/dist-packages"),
    ("/usr/local", "/usr/local/lib/python3.11/site-packages/", pyenv, pyenv[0]),
    ("/h/.local", "/h/.local/lib/python3.11/site-packages/", pyenv, pyenv[1]),
    ("/usr/local", "/h/venv/lib/python3.11/site-packages", venv, venv[0]),
    ("/opt/acbb", "/opt/acbb/lib/python3.11/site-packages", pyenv, pyenv[0]),
]
for prefix, meson_dir, dirs, want in cases:
    got = choose(prefix, meson_dir, dirs, dirs[0])
    print("ok" if got == want else "BAD", prefix, meson_dir, "->", got, "want", want)
PY
[ "$(grep -c '^ok ' "$TMP/site.txt")" -eq 6 ] && ! grep -q -v '^ok ' "$TMP/site.txt"
t $? "site_dir.py: Debian /usr and /usr/local, pyenv /usr/local and ~/.local, a venv, /opt$(grep -v '^ok ' "$TMP/site.txt" | head -3 | tr '\n' ' ')"
if [ "$SAN" = none ] && command -v python3 >/dev/null; then
    mkdir -p "$TMP/elsewhere" "$TMP/xdg"
    (cd "$TMP/elsewhere" && env -u ACBB_LIB XDG_CONFIG_HOME="$TMP/xdg" \
        PYTHONPATH="$(dirname "$PYMOD")" python3 -c 'import acbb
print("version", acbb.__version__)
r = acbb.run("7008C")
print(r["status"], "%.17g" % r["losses_W"]["total"])') >"$TMP/py.txt" 2>"$TMP/err"
    has "$TMP/py.txt" "converged $(val losses_W.total)" \
        "the installed module runs the installed preset 7008C by name with the installed library"
    has "$TMP/py.txt" "version $("$ACBB" --version | awk '{ print $2 }')" \
        "acbb.__version__ is the release acbb --version prints"
else
    skip "the installed module runs 7008C by name" "sanitizer build or no python3"
    skip "acbb.__version__" "sanitizer build or no python3"
fi

LD_LIBRARY_PATH=$LIB "$TMP/ex" presets/no-such.ini >/dev/null 2>"$TMP/err"
code $? 2 "a missing preset exits 2"
has "$TMP/err" "presets/no-such.ini: cannot open" "with the engine's message"

tap_done
