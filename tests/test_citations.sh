#!/bin/sh
# Users get the repository's own physics reference, docs/physics.md, and no
# citation of a file a clone or an install does not have (issue 28 items 10
# and 13), TAP:
# - docs/physics.md numbers its sections 0..17 (## §N, ### §N.M);
# - README.md, BENCHMARKS.md, docs/*.md, the presets, contrib, and the
#   string literals of cli/, src/, ui/, completion/ and examples/ (comments
#   stripped by the C preprocessor: code comments may cite the developers'
#   specification) never name MODEL.md, nor does what the program prints
#   (acbb help, the man page, acbb keys, acbb presets);
# - every "docs/physics.md §N" / "docs/physics.md section N" there, and
#   every "§N" inside docs/physics.md, names a section that exists;
# - no "issue N" (the developers' tracker) in what the program prints, in
#   its string literals, nor in README.md and docs/*.md.
# Usage: test_citations.sh PATH/TO/acbb   (cwd = repo root)
set -u
ACBB=${1:?usage: test_citations.sh PATH/TO/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-cite.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
DOC=docs/physics.md
CC=${CC:-cc}

# ---- the reference and its section numbers ----
[ -s "$DOC" ]
t $? "$DOC exists"
sed -n -E 's/^#{2,3} §([0-9]+(\.[0-9]+)?) .*/\1/p' "$DOC" >"$TMP/heads"
grep -v '\.' "$TMP/heads" >"$TMP/top"
seq 0 17 | cmp -s - "$TMP/top"
t $? "$DOC has sections §0..§17, each once and in order ($(tr '\n' ' ' <"$TMP/top"))"

# ---- user-facing files: no MODEL.md ----
files="README.md BENCHMARKS.md $(ls docs/*.md) $(ls presets/*.ini) $(find contrib -type f)"
# shellcheck disable=SC2086
grep -n -E 'MODEL\.md|\.\./shared/' $files >"$TMP/hits" 2>/dev/null
[ ! -s "$TMP/hits" ]
t $? "no MODEL.md nor ../shared/ in README, BENCHMARKS, docs, presets, contrib$( [ -s "$TMP/hits" ] && printf ' (at %s)' "$(cut -d: -f1,2 "$TMP/hits" | head -5 | tr '\n' ' ')")"

# String literals of the program (comments stripped, macros not expanded).
: >"$TMP/src"
: >"$TMP/alltext"
for f in cli/*.c cli/*.h src/*/*.c src/*/*.h ui/*.c ui/*.h completion/*.c examples/*.c \
         include/acbb/*.h; do
    # only files that name either document can cite one (cpp is the slow part)
    [ -f "$f" ] && grep -q -E 'MODEL\.md|physics\.md' "$f" || continue
    "$CC" -fpreprocessed -dD -E -P "$f" 2>/dev/null >"$TMP/one" || { echo "$f: cpp failed" >>"$TMP/src"; continue; }
    grep -q 'MODEL\.md' "$TMP/one" && echo "$f" >>"$TMP/src"
    cat "$TMP/one" >>"$TMP/alltext"
done
[ ! -s "$TMP/src" ]
t $? "no MODEL.md in the program's strings$( [ -s "$TMP/src" ] && printf ' (in %s)' "$(head -5 "$TMP/src" | tr '\n' ' ')")"

# What the program prints.
"$ACBB" help >"$TMP/out" 2>&1
"$ACBB" help --man >>"$TMP/out" 2>&1
"$ACBB" keys >>"$TMP/out" 2>&1
"$ACBB" presets >>"$TMP/out" 2>&1
[ -s "$TMP/out" ] && ! grep -q 'MODEL\.md' "$TMP/out"
t $? "acbb help, the man page, acbb keys and acbb presets name no MODEL.md"

# ---- no issue numbers in what users read ----
# "issue 18" means something to the developers' tracker only: help texts
# say what they mean (the key help of mounting.tilt said "the tilt before
# issue 18"). What the program prints: the overview, every command's
# --help, the man page, keys, metrics, the JSON schema; and every string
# literal of the program (the TUI's help lines, its messages).
"$ACBB" --help >"$TMP/help" 2>&1
for c in $("$ACBB" help 2>/dev/null | awk '/^commands:/ { on = 1; next } /^$/ { on = 0 }
                                          on && /^  [a-z]/ { print $1 ($1 == "bench" ? "_" $2 : "") }'); do
    # shellcheck disable=SC2046
    "$ACBB" $(echo "$c" | tr _ ' ') --help >>"$TMP/help" 2>&1
    echo "$c" >>"$TMP/cmds"
done
"$ACBB" metrics >>"$TMP/help" 2>&1
"$ACBB" schema >>"$TMP/help" 2>&1
cat "$TMP/out" >>"$TMP/help"
ISSUE='[Ii]ssues? +#?[0-9]'
[ "$(wc -l <"$TMP/cmds")" -ge 20 ] && grep -q 'mounting.tilt' "$TMP/help" &&
    ! grep -E "$ISSUE" "$TMP/help" >"$TMP/hits"
t $? "no 'issue N' in acbb --help, $(wc -l <"$TMP/cmds") commands' --help, the man page, keys, metrics, schema$( [ -s "$TMP/hits" ] && printf ' (%s)' "$(head -3 "$TMP/hits" | tr '\n' ' ')")"
: >"$TMP/src"
for f in cli/*.c cli/*.h src/*/*.c src/*/*.h ui/*.c ui/*.h completion/*.c include/acbb/*.h \
         include/acbb/tools/*.h; do
    [ -f "$f" ] && grep -q -E "$ISSUE" "$f" || continue
    "$CC" -fpreprocessed -dD -E -P "$f" 2>/dev/null >"$TMP/one" || { echo "$f: cpp failed" >>"$TMP/src"; continue; }
    grep -q -E "$ISSUE" "$TMP/one" && echo "$f" >>"$TMP/src"
done
[ ! -s "$TMP/src" ]
t $? "no 'issue N' in the program's strings (the TUI's help included)$( [ -s "$TMP/src" ] && printf ' (in %s)' "$(head -5 "$TMP/src" | tr '\n' ' ')")"
# README.md and docs/*.md are read by users too: "(issue 18, tilt)" there
# pointed at nothing they can open. BENCHMARKS.md is the developers' log
# and may cite the tracker.
userdocs=$(ls README.md docs/*.md | grep -v -x -e BENCHMARKS.md)
# shellcheck disable=SC2086
grep -n -E "$ISSUE" $userdocs >"$TMP/hits"
[ -n "$userdocs" ] && [ ! -s "$TMP/hits" ]
t $? "no 'issue N' in README.md and docs/*.md ($(echo $userdocs | wc -w) files)$( [ -s "$TMP/hits" ] && printf ' (at %s)' "$(cut -d: -f1,2 "$TMP/hits" | head -5 | tr '\n' ' ')")"

# ---- every citation names an existing section ----
# shellcheck disable=SC2086
cat $files "$TMP/alltext" "$TMP/out" | tr '\n' ' ' |
    grep -o -E 'docs/physics\.md +(§|sections? +)[0-9]+(\.[0-9]+)?' |
    sed -E 's/.*[^0-9.]([0-9]+(\.[0-9]+)?)$/\1/' | sort -u >"$TMP/cited"
grep -o -E '§[0-9]+(\.[0-9]+)?' "$DOC" | sed 's/§//' | sort -u >>"$TMP/cited"
sort -u "$TMP/cited" -o "$TMP/cited"
miss=""
for s in $(cat "$TMP/cited"); do grep -q -x -F "$s" "$TMP/heads" || miss="$miss $s"; done
[ -s "$TMP/cited" ] && [ -z "$miss" ]
t $? "every cited section ($(wc -l <"$TMP/cited") distinct) exists in $DOC${miss:+ (missing:$miss)}"
grep -q -E 'docs/physics\.md' README.md
t $? "README.md points at docs/physics.md"

tap_done
