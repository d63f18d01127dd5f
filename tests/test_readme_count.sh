#!/bin/sh
# The README's count of the default suite's tests (issue: it said 86 when
# there were 96) is the build's, so it cannot drift again. TAP.
# The default suite is every test outside the suites the default setup
# excludes (add_test_setup in tests/meson.build), read from meson's
# introspection of the build (meson-info/intro-tests.json). The README
# counts a build with a C++ compiler (build-essential): without one the
# `cxx` test is not built and is counted as if it were.
# $1 = the build directory; cwd = repository root.
set -u
BUILD=${1:?usage: test_readme_count.sh BUILDDIR}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-count.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

excl=$(sed -n "s/^add_test_setup('default', exclude_suites : \[\(.*\)\],.*/\1/p" tests/meson.build |
       tr -d "' " | tr ',' '\n' | jq -R . | jq -cs .)
[ -n "$excl" ] && [ "$excl" != "[]" ]
t $? "the default setup's excluded suites read from tests/meson.build ($excl)"
# A suite is "PROJECT:NAME" there ("acbb" alone: no suite of its own).
have=$(jq --argjson x "$excl" '[.[] | select(all(.suite[]; sub("^[^:]*:"; "") as $s |
        $x | index([$s]) | not))] | length' "$BUILD/meson-info/intro-tests.json")
jq -e 'any(.[]; .name == "cxx")' "$BUILD/meson-info/intro-tests.json" >/dev/null || have=$((have + 1))
said=$(sed -n 's/.*names them, \([0-9][0-9]*\) tests;.*/\1/p' README.md)
[ -n "$said" ] && [ "$said" = "$have" ]
t $? "README.md gives the default suite's count, $have tests (it says ${said:-nothing})"

tap_done
