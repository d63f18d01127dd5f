#!/bin/sh
# ./dev.sh on a tree that does not compile (issue 28 item 11): it says it
# is building, exits non-zero and shows the compiler's error, where it used
# to exit 1 with nothing printed. A copy of the source tree with one
# injected #error, configured and built from scratch (~30 s of CPU: slow
# suite). TAP. cwd = repository root.
set -u
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-devsh.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
# The tracked files as they are in the work tree (no build directory).
git ls-files -z | xargs -0 -I{} cp --parents {} "$TMP/" 2>/dev/null
[ -x "$TMP/dev.sh" ]
t $? "the source tree copied"
printf '#error acbb-injected-compile-error\n' >>"$TMP/cli/main.c"
(cd "$TMP" && ./dev.sh run version) >"$TMP/out" 2>"$TMP/err"
rc=$?
[ "$rc" -ne 0 ]
t $? "a compile error: dev.sh exits non-zero (exit $rc)"
has "$TMP/err" "acbb-injected-compile-error" "the compiler's error is shown"
has "$TMP/err" "dev.sh: the build failed" "dev.sh says the build failed"
has "$TMP/err" "the first build takes about a minute" "the first build says it is building"
tap_done
