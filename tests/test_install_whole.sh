#!/bin/sh
# An install that is whole (issue 21 items 12, 13), TAP: `meson install
# --destdir` ships every preset (each runs from the installed binary by
# name), the docs, the contrib recipes (executable), LICENSE, the bash
# completion and a man page generated from the command table with every
# command, option and environment variable, the prefix's real paths and a
# date; contrib/slurm's merge runs once per submission and contrib/parallel
# fails when a shard fails.
# Usage: test_install_whole.sh PATH/TO/acbb BUILDDIR   (cwd = repo root)
set -u
ACBB=${1:?usage: test_install_whole.sh PATH/TO/acbb BUILDDIR}
BUILD=${2:?usage: test_install_whole.sh PATH/TO/acbb BUILDDIR}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-inst.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"
ROOT=$(pwd)

meson install -C "$BUILD" --destdir "$TMP/dest" --no-rebuild >"$TMP/log" 2>&1
code $? 0 "meson install --destdir"
BIN=$(find "$TMP/dest" -path '*/bin/acbb' -type f | head -1)
PREFIX=${BIN%/bin/acbb}
PREFIX=${PREFIX#"$TMP/dest"}
SHARE="$TMP/dest$PREFIX/share"

miss=""
for p in "$ROOT"/presets/*.ini; do [ -f "$SHARE/acbb/presets/$(basename "$p")" ] || miss="$miss $(basename "$p")"; done
[ -z "$miss" ]
t $? "every preset of presets/ is installed${miss:+ (missing:$miss)}"
cd "$TMP" && XDG_CONFIG_HOME="$TMP/none" "$BIN" run te-wte-heavy --quiet >/dev/null 2>"$TMP/err"
code $? 0 "the installed acbb runs te-wte-heavy by name from another directory"
cd "$ROOT"
for f in doc/acbb/LICENSE doc/acbb/README.md doc/acbb/BENCHMARKS.md doc/acbb/docs/SEED_REPORT.md \
         doc/acbb/docs/physics.md acbb/schema/acbb.schema.json bash-completion/completions/acbb; do
    [ -s "$SHARE/$f" ] || miss="$miss $f"
done
[ -z "$miss" ]
t $? "LICENSE, docs, the JSON Schema and the bash completion are installed${miss:+ (missing:$miss)}"
[ -x "$SHARE/acbb/contrib/slurm/acbb-sweep.sbatch" ] && [ -x "$SHARE/acbb/contrib/parallel/acbb-sweep-parallel.sh" ]
t $? "the contrib recipes are installed executable"
grep -q "MIT License" "$SHARE/doc/acbb/LICENSE"
t $? "LICENSE is the MIT licence meson.build declares"
cmp -s "$SHARE/doc/acbb/docs/physics.md" docs/physics.md && grep -q '^## §17 ' "$SHARE/doc/acbb/docs/physics.md"
t $? "the physics reference the help and README cite is installed whole (doc/acbb/docs/physics.md)"
! grep -q 'MODEL\.md' "$SHARE/doc/acbb/README.md" "$SHARE/doc/acbb/BENCHMARKS.md" "$SHARE"/doc/acbb/docs/*.md \
    "$SHARE/man/man1/acbb.1" "$SHARE"/acbb/presets/*.ini
t $? "the installed README, docs, man page and presets cite no unshipped MODEL.md"

# Every document the installed ones point to is installed: a path
# "docs/NAME" (as the text cites them, from the repository's root, which
# share/doc/acbb mirrors) and a Markdown link [..](TARGET) (from the
# linking file's directory). Parsed from the installed files themselves.
DOC=$SHARE/doc/acbb
: >"$TMP/links"
for f in "$DOC"/*.md "$DOC"/docs/*.md; do
    grep -oE '(^|[^A-Za-z0-9_/.-])docs/[A-Za-z0-9_.-]+[.](md|csv|png|txt)' "$f" |
        sed "s|^[^d]*|$f $DOC/|"
    grep -oE '\]\([^)#[:space:]]+' "$f" | sed 's/^](//' | grep -vE '^[a-z]+:' |
        sed "s|^|$f ${f%/*}/|"
done | sort -u >"$TMP/links"
miss=$(while read -r from to; do [ -e "$to" ] || printf ' %s -> %s' "${from#"$DOC"/}" "${to#"$DOC"/}"; done <"$TMP/links")
[ "$(wc -l <"$TMP/links")" -ge 10 ] && [ -z "$miss" ]
t $? "every docs/ file the installed README, BENCHMARKS and docs cite is installed ($(wc -l <"$TMP/links") references)${miss:+; missing:$miss}"

# ---- the completion: every command, and a command's options ----
comp="$SHARE/bash-completion/completions/acbb"
bash -c ". '$comp' && complete -p acbb" >/dev/null 2>&1
t $? "the completion loads in bash and registers acbb"
cmds=$("$ACBB" help | sed -n 's/^  \([a-z]*\) .*/\1/p' | sort -u)
miss=""
for c in $cmds; do
    out=$(bash -c ". '$comp'; COMP_WORDS=(acbb '${c%?}'); COMP_CWORD=1; _acbb; echo \"\${COMPREPLY[*]}\"")
    echo " $out " | grep -q " $c " || miss="$miss $c"
done
[ -n "$cmds" ] && [ -z "$miss" ]
t $? "the completion completes every command of acbb help${miss:+ (missing:$miss)}"
out=$(bash -c ". '$comp'; COMP_WORDS=(acbb run --bas); COMP_CWORD=2; _acbb; echo \"\${COMPREPLY[*]}\"")
[ "$out" = "--baseline" ]
t $? "and a command's options (acbb run --bas -> $out)"
out=$(bash -c ". '$comp'; COMP_WORDS=(acbb bench acc); COMP_CWORD=2; _acbb; echo \"\${COMPREPLY[*]}\"")
[ "$out" = "accuracy" ]
t $? "and the second word of a two-word command (bench acc -> $out)"

# ---- the man page ----
man="$TMP/dest$PREFIX/share/man/man1/acbb.1"
[ -s "$man" ]
t $? "acbb.1 is installed"
miss=""
for c in $cmds; do grep -q "^\\\\fBacbb $c" "$man" || miss="$miss $c"; done
for o in baseline no-mouse json size bash-completion plot-dir; do
    grep -F -q -- "$(echo "--$o" | sed 's/-/\\-/g')" "$man" || miss="$miss --$o"
done
for e in ACBB_PROGRESS ACBB_ASCII ACBB_GNUPLOT NO_COLOR XDG_STATE_HOME XDG_CONFIG_HOME; do
    grep -q "^\.B $e" "$man" || miss="$miss $e"
done
[ -z "$miss" ]
t $? "the man page has every command, the options and environment variables asked for${miss:+ (missing:$miss)}"
grep -q "^\.I $PREFIX/share/acbb/presets" "$man" && ! grep -q "DATADIR/acbb" "$man"
t $? "it names the prefix's real preset directory ($PREFIX/share/acbb/presets)"
# Issue 28 item 13: the minimums are lower limits; an example stands on its
# own unfilled lines, not run into the prose around it.
grep -A1 -F -e '\-\-min\-life' -e '\-\-min\-s0' "$man" | grep -c '^lower limit:' | grep -q '^2$' \
    && ! grep -q 'upper limit: .* at least' "$man"
t $? "--min-life and --min-s0 are described as lower limits"
grep -A2 -x '\.nh' "$man" | grep -q -x 'e\.g\. acbb study seed \\-\\-out figs' \
    && ! grep -q 'cite them\. e\.g\.' "$man"
t $? "an example is on its own unfilled line (e.g. acbb study seed --out figs)"
grep -q "acbb/recover" "$man"
t $? "and where the TUI's recovery files go"
grep -q '^\.TH ACBB 1 "[0-9]\{4\}-[0-9][0-9]-[0-9][0-9]"' "$man"
t $? "and has a date ($(grep '^\.TH' "$man"))"
MANWIDTH=80 man -l "$man" 2>/dev/null >"$TMP/man.txt"
if [ -s "$TMP/man.txt" ]; then
    [ "$(awk 'length > 80' "$TMP/man.txt" | wc -l)" -eq 0 ]
    t $? "rendered at 80 columns no line is longer ($(awk 'length > 80' "$TMP/man.txt" | head -1))"
else
    skip "man page at 80 columns" "man(1) cannot render here"
fi

# ---- contrib: one merge per submission, parallel's exit status ----
cat >"$TMP/fake-acbb" <<EOS
#!/bin/sh
# fails shard 2/2 when FAIL_SHARD is set; counts merges
case "\$1" in merge) echo x >>"$TMP/merges" ;; esac
case "\$*" in *"--shard 2/2"*) [ -n "\${FAIL_SHARD:-}" ] && exit 4 ;; esac
exec "$ACBB" "\$@"
EOS
chmod +x "$TMP/fake-acbb"
mkdir -p "$TMP/sl"
"$ACBB" sweep presets/7008C.ini --set fidelity.model=static --grid operating.axial_load_N=200,400 \
    --jsonl "$TMP/sl/shard-1.jsonl" >/dev/null 2>&1
for task in 1 2; do
    ACBB="$TMP/fake-acbb" SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=2 \
        contrib/slurm/acbb-sweep.sbatch --merge "$TMP/sl" >/dev/null 2>&1
done
[ "$(wc -l <"$TMP/merges" 2>/dev/null)" -eq 1 ] && [ -s "$TMP/sl/sweep.jsonl" ]
t $? "slurm: a merge submitted as a 2-task array merges once (task 1), not twice"
if command -v parallel >/dev/null 2>&1; then
    ACBB="$TMP/fake-acbb" ACBB_JOBS=1 contrib/parallel/acbb-sweep-parallel.sh 2 "$TMP/p1" \
        presets/7008C.ini --set fidelity.model=static --grid operating.axial_load_N=200,400 >/dev/null 2>&1
    code $? 0 "parallel: every shard ran -> exit 0"
    FAIL_SHARD=1 ACBB="$TMP/fake-acbb" ACBB_JOBS=1 contrib/parallel/acbb-sweep-parallel.sh 2 "$TMP/p2" \
        presets/7008C.ini --set fidelity.model=static --grid operating.axial_load_N=200,400 >/dev/null 2>"$TMP/err"
    code $? 1 "parallel: a failed shard -> exit 1"
    grep -q "1 shard(s) failed" "$TMP/err"
    t $? "and it says so: $(grep "shard(s) failed" "$TMP/err")"
else
    skip "parallel exit status" "GNU parallel not installed"
fi
tap_done
