#!/usr/bin/env bash
# Layering rules of the house (DESIGN.md; README "Source tree"):
# (1) there is ONE run loop, acbb_sim_drive in src/run/sim.c; no client
# (cli/, ui/) and no other engine file calls acbb_sim_step itself;
# (2) the engine (include/, src/) includes no ncurses and prints nothing to
# stdout/stderr; (3) the clients include only the public API
# (include/acbb/*.h) and their own headers, never an engine internal;
# (4) no engine message names a CLI flag (--set, --grid, ...): the TUI shows
# the same messages. Comments are blanked first (and, for 1-2, string
# literals), so prose that names a function does not count; every hit is
# reported as file:line.
# Run from the source root (meson's workdir); optional $1: another root.
set -u
cd "${1:-$(dirname "$0")/..}" || exit 1
. tests/tap.sh

# strip FILE: the file with comments and string/char literals blanked,
# line numbers preserved.
strip() {
    awk '
    BEGIN { incomment = 0 }
    {
        out = ""; i = 1; n = length($0); s = $0
        while (i <= n) {
            c = substr(s, i, 1); c2 = substr(s, i, 2)
            if (incomment) {
                if (c2 == "*/") { incomment = 0; i += 2 } else i++
                continue
            }
            if (c2 == "/*") { incomment = 1; i += 2; continue }
            if (c2 == "//") break
            if (c == "\"" || c == "\047") {
                q = c; out = out q; i++
                while (i <= n) {
                    c = substr(s, i, 1)
                    if (c == "\\") { i += 2; continue }
                    i++
                    if (c == q) break
                }
                out = out q
                continue
            }
            out = out c; i++
        }
        print out
    }' "$1"
}

# hits PATTERN FILE...: "file:line: text" for every code line matching the
# extended regular expression PATTERN.
hits() {
    pat=$1; shift
    for f in "$@"; do
        [ -f "$f" ] || continue
        c="$TMP/stripped/$f"        # each file is stripped once
        [ -f "$c" ] || { mkdir -p "$(dirname "$c")" && strip "$f" >"$c"; }
        grep -n -E -- "$pat" "$c" | sed "s|^|$f:|"
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

# Self-check of the scanner on known text, so a broken stripper or pattern
# cannot pass silently.
printf '%s\n' '/* acbb_sim_step( in a comment */' 'x = "acbb_sim_step(";' \
    '  rc = acbb_sim_step (sim); // step' > "$TMP/probe.c"
[ "$(hits 'acbb_sim_step[[:space:]]*\(' "$TMP/probe.c")" = "$TMP/probe.c:3:  rc = acbb_sim_step (sim); " ]
t $? "scanner: finds a call, ignores comments and strings"

step='(^|[^[:alnum:]_])acbb_sim_step[[:space:]]*\('
curses='^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"](ncursesw?/)?n?curses'
print='(^|[^[:alnum:]_])(v?printf|puts|putchar|perror)[[:space:]]*\(|(^|[^[:alnum:]_])v?f(printf|puts)[[:space:]]*\([^,]*,[[:space:]]*(stdout|stderr)|(^|[^[:alnum:]_])v?fprintf[[:space:]]*\([[:space:]]*(stdout|stderr)'
printf '%s\n' '#include <ncursesw/curses.h>' 'snprintf(b, n, "%d", 1);' 'fprintf(f, "%d", 1);' \
    ' fprintf( stderr, "x");' 'fputs(msg, stdout);' 'puts("x");' > "$TMP/probe2.c"
[ "$(hits "$curses" "$TMP/probe2.c" | cut -d: -f2)" = 1 ] \
    && [ "$(hits "$print" "$TMP/probe2.c" | cut -d: -f2 | tr '\n' ' ')" = "4 5 6 " ]
t $? "scanner: finds ncurses includes and printing, not snprintf or fprintf to a file"

[ ${#clients[@]} -gt 3 ] && [ ${#others[@]} -gt 10 ]
t $? "found the client (${#clients[@]}) and engine (${#others[@]}) sources"

check "no client calls acbb_sim_step (the one run loop is acbb_sim_drive)" "$step" \
    "${clients[@]}"
check "no engine file but src/run/sim.c calls acbb_sim_step" "$step" "${others[@]}"
check "the engine does not include ncurses" "$curses" "${engine[@]}"
check "the engine does not print (printf, puts, fprintf/fputs to stdout or stderr)" \
    "$print" "${engine[@]}"

# (3) Clients include the public API and their own headers only. The
# include lines are read as they are (a quoted name is the point here).
bad_inc=""
for f in "${clients[@]}"; do
    dir=$(dirname "$f")
    while IFS=: read -r ln name; do
        case "$name" in
            acbb/*) [ -f "include/$name" ] || bad_inc+="$f:$ln: $name (not public)"$'\n' ;;
            *) [ -f "$dir/$name" ] || [ -f "cli/$name" ] || [ -f "ui/$name" ] || bad_inc+="$f:$ln: $name (engine internal)"$'\n' ;;
        esac
    done < <(grep -n -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$f" \
             | sed -E 's/^([0-9]+):[^"]*"([^"]*)".*/\1:\2/')
done
[ -z "$bad_inc" ]
t $? "cli/ and ui/ include only include/acbb/*.h and their own (cli/, ui/) headers"
[ -z "$bad_inc" ] || printf '%s' "$bad_inc" | sed 's/^/#   /'
printf '%s\n' '#include "acbb/sim.h"' '#include "hertz.h"' > "$TMP/probe3.c"
[ "$(grep -c -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$TMP/probe3.c")" = 2 ]
t $? "scanner: reads quoted includes"
ls include/acbb/hertz.h include/acbb/mechanics.h include/acbb/broyden.h >/dev/null 2>&1
t $(( $? == 0 )) "internals (hertz.h, mechanics.h, broyden.h) are not in include/acbb"

# (4) Engine messages are shown by the CLI and the TUI alike: a literal
# that names a CLI flag (--set, --grid, --jobs ...) belongs to the CLI.
flag='"[^"]*(^|[^[:alnum:]-])--[a-z][a-z-]+'
msgs() {
    for f in "$@"; do
        # comments out, strings kept
        awk 'BEGIN{c=0} { o=""; s=$0; n=length(s); i=1
             while (i<=n) { a=substr(s,i,2)
               if (c) { if (a=="*/") {c=0; i+=2} else i++; continue }
               if (a=="/*") {c=1; i+=2; continue}
               if (a=="//") break
               o=o substr(s,i,1); i++ }
             print o }' "$f" | grep -n -E -- "$flag" | sed "s|^|$f:|"
    done
}
printf '%s\n' 'e = "use --grid k=v";  /* "--set" in a comment */' 'x = a--b;' > "$TMP/probe4.c"
[ "$(msgs "$TMP/probe4.c" | cut -d: -f2)" = 1 ]
t $? "scanner: finds a flag in a string, not in a comment or an expression"
found=$(msgs "${engine[@]}")
[ -z "$found" ]
t $? "no engine message names a CLI flag"
[ -z "$found" ] || printf '%s\n' "$found" | sed 's/^/#   /'

tap_done
