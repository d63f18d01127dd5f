#!/usr/bin/env bash
# Layering rules of the house (DESIGN.md; README "Source tree"):
# (1) there is ONE run loop, acbb_sim_drive in src/run/sim.c; no client
# (cli/, ui/) and no other engine file calls acbb_sim_step itself;
# (2) the engine (include/, src/) includes no ncurses and prints nothing to
# stdout/stderr; (3) the clients include only the public API
# (include/acbb/*.h), the tools (include/acbb/tools/*.h) and their own
# headers, never an engine internal;
# (4) no engine message names a CLI flag (--set, --grid, ...): the TUI shows
# the same messages. Comments are blanked first (and, for 1-2, string
# literals), so prose that names a function does not count; every hit is
# reported as file:line; (5) src/ folders include only their own or lower
# folders' internal headers; (6) the same order on symbols: what each built
# object references against what the others define (layer_symbols.py).
# usage: test_layers.sh [ROOT [LIB EXE]]: ROOT the source root (default:
# this script's); LIB, EXE the built libacbb.a and acbb (meson passes them;
# without them (6) checks its own scanner only).
set -u
cd "${1:-$(dirname "$0")/..}" || exit 1
LIB=${2:-} EXE=${3:-}
. tests/tap.sh

# strip_all DIR KEEP FILE...: each FILE with comments (and, KEEP=0, string
# and char literals) blanked into DIR/FILE, line numbers preserved. One
# python3 process for the whole tree (a per-file scanner took 15 s or more).
strip_all() {
    python3 - "$@" <<'PYX'
import os, sys
dest, keep = sys.argv[1], sys.argv[2] == "1"
for path in sys.argv[3:]:
    src = open(path, encoding="utf-8", errors="replace").read()
    out, i, n, com = [], 0, len(src), False
    while i < n:
        c = src[i]
        if com:
            if src.startswith("*/", i): com = False; i += 2
            else:
                if c == "\n": out.append(c)
                i += 1
            continue
        if src.startswith("/*", i): com = True; i += 2; continue
        if src.startswith("//", i):
            while i < n and src[i] != "\n": i += 1
            continue
        if c in "\"'":
            j = i + 1
            while j < n and src[j] != c and src[j] != "\n":
                j += 2 if src[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(src[i:j] if keep else c + c); i = j; continue
        out.append(c); i += 1
    target = os.path.join(dest, path.lstrip("/"))
    os.makedirs(os.path.dirname(target), exist_ok=True)
    open(target, "w").write("".join(out))
PYX
}

# hits PATTERN FILE...: "file:line: text" for every code line matching the
# extended regular expression PATTERN (STRIPPED: the blanked copies' root).
hits() {
    pat=$1; shift
    root="${STRIPPED:-$TMP/stripped}"
    rel=()
    for f in "$@"; do
        [ -f "$root/${f#/}" ] || strip_all "$root" "${KEEP:-0}" "$f"
        rel+=("${f#/}")
    done
    [ ${#rel[@]} -gt 0 ] || return 0
    # One grep over the blanked copies; names print as given (an absolute
    # probe path gets its leading slash back).
    (cd "$root" && grep -n -E -H -- "$pat" "${rel[@]}") \
        | while IFS= read -r line; do
            for f in "$@"; do
                case "$line" in "${f#/}:"*) printf '%s\n' "$f${line#"${f#/}"}"; break ;; esac
            done
        done
}

# check NAME PATTERN FILE...: one TAP result; the hits are listed on failure.
check() {
    name=$1; pat=$2; shift 2
    found=$(hits "$pat" "$@")
    [ -z "$found" ]
    t $? "$name"
    [ -z "$found" ] || printf '%s\n' "$found" | sed 's/^/#   /'
}

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
shopt -s nullglob globstar
clients=(cli/**/*.[ch] ui/**/*.[ch])
engine=(include/**/*.h)
others=()
for f in src/**/*.[ch]; do
    case "$f" in
        src/run/sim.c) engine+=("$f") ;;
        *) engine+=("$f"); others+=("$f") ;;
    esac
done

strip_all "$TMP/stripped" 0 "${engine[@]}" "${clients[@]}"

# Self-check of the scanner on known text, so a broken stripper or pattern
# cannot pass silently.
printf '%s\n' '/* acbb_sim_step( in a comment */' 'x = "acbb_sim_step(";' \
    '  rc = acbb_sim_step (sim); // step' > "$TMP/probe.c"
[ "$(hits 'acbb_sim_step[[:space:]]*\(' "$TMP/probe.c")" = "$TMP/probe.c:3:  rc = acbb_sim_step (sim); " ]
t $? "scanner: finds a call, ignores comments and strings"

step='(^|[^[:alnum:]_])acbb_sim_step[[:space:]]*\('
curses='^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"](ncursesw?/)?n?curses'
print='(^|[^[:alnum:]_])(v?printf|puts|putchar|perror)[[:space:]]*\(|(^|[^[:alnum:]_])(stdout|stderr)([^[:alnum:]_]|$)|(^|[^[:alnum:]_])v?dprintf[[:space:]]*\([[:space:]]*[12][[:space:]]*,|(^|[^[:alnum:]_])write[[:space:]]*\([[:space:]]*(1|2|STDOUT_FILENO|STDERR_FILENO)[[:space:]]*,'
printf '%s\n' '#include <ncursesw/curses.h>' 'snprintf(b, n, "%d", 1);' 'fprintf(f, "%d", 1);' \
    ' fprintf( stderr, "x");' 'fputs(msg, stdout);' 'puts("x");' 'fwrite(b, 1, n, stderr);' \
    'dprintf(2, "x");' 'write(STDERR_FILENO, b, n);' 'fputc(c, f); my_stdout_x = 1;' > "$TMP/probe2.c"
[ "$(hits "$curses" "$TMP/probe2.c" | cut -d: -f2)" = 1 ] \
    && [ "$(hits "$print" "$TMP/probe2.c" | cut -d: -f2 | tr '\n' ' ')" = "4 5 6 7 8 9 " ]
t $? "scanner: finds ncurses includes and printing (printf, puts, any use of stdout/stderr, fd 1/2), not snprintf or fprintf to a file"

[ ${#clients[@]} -gt 3 ] && [ ${#others[@]} -gt 10 ]
t $? "found the client (${#clients[@]}) and engine (${#others[@]}) sources"

check "no client calls acbb_sim_step (the one run loop is acbb_sim_drive)" "$step" \
    "${clients[@]}"
check "no engine file but src/run/sim.c calls acbb_sim_step" "$step" "${others[@]}"
check "the engine does not include ncurses" "$curses" "${engine[@]}"
# src/base/outfile.c alone may name stdout: the atomic writer's "-" target is
# the caller's stdout (outfile.h); it writes only what a client hands it.
quiet=()
for f in "${engine[@]}"; do [ "$f" = src/base/outfile.c ] || quiet+=("$f"); done
check "the engine does not print (printf, puts, stdout/stderr, fd 1/2; outfile.c's \"-\" aside)" \
    "$print" "${quiet[@]}"

# (3) Clients include the public API and their own headers only. The
# include lines are read as they are (a quoted name is the point here).
bad_inc=""
for f in "${clients[@]}"; do
    dir=${f%/*}
    while IFS=: read -r ln name; do
        case "$name" in
            ../cli/*|../ui/*) [ -f "$dir/$name" ] || bad_inc+="$f:$ln: $name (missing)"$'\n' ;;
            *..*|*src/*|*include/*) bad_inc+="$f:$ln: $name (a path into the engine)"$'\n' ;;
            acbb/*) [ -f "include/$name" ] || bad_inc+="$f:$ln: $name (not public)"$'\n' ;;
            *) [ -f "$dir/$name" ] || [ -f "cli/$name" ] || [ -f "ui/$name" ] || bad_inc+="$f:$ln: $name (engine internal)"$'\n' ;;
        esac
    done < <(grep -n -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$f" \
             | sed -E 's/^([0-9]+):[^"]*"([^"]*)".*/\1:\2/')
done
[ -z "$bad_inc" ]
t $? "cli/ and ui/ include only include/acbb/*.h, include/acbb/tools/*.h and their own (cli/, ui/) headers"
[ -z "$bad_inc" ] || printf '%s' "$bad_inc" | sed 's/^/#   /'
printf '%s\n' '#include "acbb/sim.h"' '#include "hertz.h"' > "$TMP/probe3.c"
[ "$(grep -c -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$TMP/probe3.c")" = 2 ]
t $? "scanner: reads quoted includes"
ls include/acbb/hertz.h include/acbb/mechanics.h include/acbb/broyden.h >/dev/null 2>&1
t $(( $? == 0 )) "internals (hertz.h, mechanics.h, broyden.h) are not in include/acbb"

# (4) Engine messages are shown by the CLI and the TUI alike: a literal
# that names a CLI flag (--set, --grid, --jobs ...) belongs to the CLI.
flag='"([^"]*[^[:alnum:]"-])?--[a-z][a-z-]+'
msgs() { STRIPPED="$TMP/kept" KEEP=1 hits "$flag" "$@"; }
printf '%s\n' 'e = "use --grid k=v";  /* "--set" in a comment */' 'x = a--b;' \
    '    "--jobs N: workers"' 'y = "a-b--c";' > "$TMP/probe4.c"
[ "$(msgs "$TMP/probe4.c" | cut -d: -f2 | tr '\n' ' ')" = "1 3 " ]
t $? "scanner: finds a flag in a string, not in a comment or an expression"
strip_all "$TMP/kept" 1 "${engine[@]}"
found=$(msgs "${engine[@]}")
[ -z "$found" ]
t $? "no engine message names a CLI flag"
[ -z "$found" ] || printf '%s\n' "$found" | sed 's/^/#   /'

# (4b) Every public header (the core, include/acbb/*.h) is in the umbrella
# acbb.h; it and every tools header (include/acbb/tools/*.h: they serve
# the CLI and the TUI, issue 27 item 5) has extern "C" guards and names no
# C11 atomic_int (acbb_atomic_int: cancel_flag.h), so a C++ host can
# include it (issue 28 item 5); no core header includes a tools header, so
# the installed core stands alone.
bad_pub=""
tools_inc='^#[[:space:]]*include[[:space:]]*["<]acbb/tools/'
for f in include/acbb/*.h include/acbb/tools/*.h; do
    h=${f#include/}
    case $h in
        acbb/tools/*) ;;
        *) grep -q "$tools_inc" "$f" && bad_pub+="$f: a core header includes a tools header"$'\n'
           case $h in acbb/acbb.h|acbb/cancel_flag.h) continue ;; esac
           grep -q "^#include \"$h\"" include/acbb/acbb.h || bad_pub+="$f: not in acbb.h"$'\n' ;;
    esac
    grep -q 'extern "C"' "$f" || bad_pub+="$f: no extern \"C\""$'\n'
    grep -Eq '(^|[^_])atomic_int|_Atomic' "$f" && bad_pub+="$f: C11 atomics in a public type"$'\n'
done
tools=(include/acbb/tools/*.h)
[ -z "$bad_pub" ] && [ ${#tools[@]} -gt 5 ]
t $? "every core header is in acbb.h and includes no tools header; core and tools (${#tools[@]}) headers have extern \"C\" and no C11 atomic type"
[ -z "$bad_pub" ] || printf '%s' "$bad_pub" | sed 's/^/#   /'

# (5) Layer order (README "Source tree"): an engine folder includes internal
# headers only from folders below it: base < physics < scene < run < batch < io.
declare -A rank=([base]=-1 [physics]=0 [scene]=1 [run]=2 [batch]=3 [io]=4) home=()
for f in src/*/*.h; do h=${f##*/}; d=${f%/*}; home[$h]=${d##*/}; done
bad_layer=""
for f in src/*/*.[ch]; do
    d=${f%/*}; d=${d##*/}
    while IFS= read -r h; do
        hd=${home[$h]:-}
        [ -z "$hd" ] || [ "${rank[$hd]}" -le "${rank[$d]}" ] ||
            bad_layer+="$f: $h ($d includes $hd)"$'\n'
    done < <(sed -n -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"/]+)".*/\1/p' "$f")
done
[ -z "$bad_layer" ]
t $? "src/ layers include only headers of their own or lower layers (base < physics < scene < run < batch < io)"
[ -z "$bad_layer" ] || printf '%s' "$bad_layer" | sed 's/^/#   /'

# (6) The order on calls: an include of a public or tools header
# (acbb/status.h, acbb/tools/surroundings.h) crosses folders unseen by (5),
# a call through it leaves an undefined symbol in the caller's object; where
# a function is declared does not matter here. layer_symbols.py maps each
# object to its folder and lists references upward, into a client (cli/,
# ui/), cycles between folders and objects of no ranked folder.
ranks=$(for d in "${!rank[@]}"; do printf '%s=%s,' "$d" "${rank[$d]}"; done)
ranks=${ranks%,}
layer_symbols() { python3 tests/layer_symbols.py "$ranks" "$@"; }
# Self-test on synthetic `nm -A -P` text: a clean tree (base < physics <
# scene < run < batch, a CLI on top) and one injection of each kind.
clean='lib.a[src_base_status.c.o]: acbb_error_set T 0 10
lib.a[src_physics_net.c.o]: acbb_error_set U
lib.a[src_physics_net.c.o]: acbb_net T 0 10
lib.a[src_scene_rules.c.o]: acbb_net U
lib.a[src_scene_rules.c.o]: acbb_rule T 0 10
lib.a[src_scene_rules.c.o]: static_helper t 20 10
lib.a[src_run_sim.c.o]: acbb_rule U
lib.a[src_run_sim.c.o]: acbb_sim_run T 0 10
lib.a[src_batch_fp.c.o]: acbb_fp T 0 10
lib.a[src_batch_fp.c.o]: malloc U
b/acbb.p/cli_main.c.o: acbb_sim_run U
b/acbb.p/cli_main.c.o: cli_flag T 0 10
b/acbb.p/ui_draw.c.o: cli_flag U'
inject() { printf '%s\n%s\n' "$clean" "$1" > "$TMP/nm.txt"; layer_symbols --nm "$TMP/nm.txt" 2>"$TMP/count"; }
[ -z "$(inject '')" ] && [ "$(cat "$TMP/count")" = "engine 5 client 2" ]
t $? "symbols scanner: a clean synthetic tree passes (5 engine, 2 client objects)"
[ "$(inject 'lib.a[src_scene_rules.c.o]: acbb_fp U')" = \
    "upward: scene/rules.c -> acbb_fp (batch/fp.c)" ]
t $? "symbols scanner: an upward call through a public header (scene calls batch)"
[ "$(inject 'lib.a[src_physics_net.c.o]: acbb_rule U')" = \
    "cycle: physics <-> scene (physics/net.c -> acbb_rule (scene/rules.c); scene/rules.c -> acbb_net (physics/net.c))
upward: physics/net.c -> acbb_rule (scene/rules.c)" ]
t $? "symbols scanner: a cycle (physics calls scene, scene calls physics)"
[ "$(inject 'lib.a[src_run_sim.c.o]: cli_flag U')" = "client: run/sim.c -> cli_flag (cli/main.c)" ]
t $? "symbols scanner: the engine calls a client symbol"
[ "$(inject 'lib.a[src_gui_x.c.o]: acbb_x T 0 10')" = "unmapped: src_gui_x.c.o" ]
t $? "symbols scanner: an object of no ranked folder"
[ -z "$(inject 'lib.a[src_batch_fp.c.o]: acbb_w W 0 1
lib.a[src_base_status.c.o]: acbb_w W 0 1
lib.a[src_physics_net.c.o]: acbb_w U')" ]
t $? "symbols scanner: a weak symbol defined in two floors counts as the lower one's"
if [ -n "$LIB" ] && [ -n "$EXE" ]; then
    found=$(layer_symbols "$LIB" "$EXE" 2>"$TMP/count")
    rc=$?
    srcs=(src/*/*.c) csrcs=(cli/**/*.c ui/**/*.c)
    [ $rc -eq 0 ] && [ -z "$found" ] && [ "$(cut -d' ' -f2 "$TMP/count")" = ${#srcs[@]} ] \
        && [ "$(cut -d' ' -f4 "$TMP/count")" -ge ${#csrcs[@]} ]
    t $? "built objects ($(cat "$TMP/count"); ${#srcs[@]} src/*/*.c, ${#csrcs[@]} cli/ ui/ .c) reference no symbol of a higher folder or a client, no cycle"
    [ -z "$found" ] || printf '%s\n' "$found" | sed 's/^/#   /'
else
    skip "built objects reference no symbol of a higher folder or a client, no cycle" "no LIB EXE given"
fi

tap_done
