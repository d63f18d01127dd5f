#!/usr/bin/env bash
# The bash completion completes option values (issue 28 item 12): --set and
# --grid keys (KEY=) and a key's choices, --kind's plot kinds, --metric's
# names, --models; a file for --csv, nothing for a number; `help` offers
# commands and a PRESET position offers presets and - (stdin), never the
# other way round. And a preset from stdin (`-`) runs as the file does.
# The script is `acbb help --bash-completion`, sourced in bash; a line is
# completed as bash does it (COMP_LINE, COMP_POINT). $1 = the acbb binary.
set -u
ACBB=$1
cd "$(dirname "$0")/.." || exit 1
. tests/tap.sh
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
"$ACBB" help --bash-completion >"$TMP/acbb.bash"
code $? 0 "acbb help --bash-completion"
mkdir "$TMP/bin" "$TMP/cwd" && ln -s "$(readlink -f "$ACBB")" "$TMP/bin/acbb"
cp presets/7008C.ini "$TMP/cwd/mine.ini"
: >"$TMP/cwd/out.csv"
mkdir -p "$TMP/xdg/acbb/presets" && cp presets/7008C.ini "$TMP/xdg/acbb/presets/userpre.ini"

# comp LINE: the replies for LINE (cursor at its end), sorted, one line.
comp() {
    (cd "$TMP/cwd" && PATH="$TMP/bin:$PATH" XDG_CONFIG_HOME="$TMP/xdg" bash -c '
        . "$1"; COMP_LINE=$2; COMP_POINT=${#2}; _acbb
        [ ${#COMPREPLY[@]} -gt 0 ] && printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "' _ "$TMP/acbb.bash" "$1")
}
# want LINE EXPECTED NAME: the replies are exactly EXPECTED (sorted words).
want() {
    local got
    got=$(comp "$1")
    [ "$got" = "$2" ]
    t $? "$3 ('$1' -> '$got')"
}

want "acbb run mine.ini --set operating.axial_l" "operating.axial_load_N= " \
    "--set completes a key, with = after it"
want "acbb run mine.ini --set fidelity.model=" "dynamic quasi-dynamic quasi-static static " \
    "--set KEY= completes the key's choices (as bash replaces after =)"
want "acbb sweep mine.ini --grid effects.heating=o" "off on " "--grid: a switch's on/off"
want "acbb sweep mine.ini --param lubricant.visc" "lubricant.viscosity_index lubricant.viscosity_model " \
    "--param completes keys"
want "acbb plot mine.ini --kind " \
    "all angles history-loads loads losses set-preload set-temperature temperature " \
    "--kind offers the plot kinds, not presets or files"
want "acbb sensitivity mine.ini --metric losses_W.to" "losses_W.total " "--metric completes result names"
want "acbb bench accuracy mine.ini --models quasi" "quasi-dynamic quasi-static " "--models completes levels"
want "acbb run mine.ini --csv ou" "out.csv " "--csv completes a file"
want "acbb run mine.ini --jobs " "" "a number (--jobs) offers nothing"
want "acbb help r" "report run " "help offers commands, not presets"
got=$(comp "acbb run ")
r=0
for w in - mine.ini userpre; do case " $got " in *" $w "*) ;; *) r=1 ;; esac; done
t $r "a PRESET position offers -, files and the names on the search path ($got)"
got=$(comp "acbb run mine.ini --b")
[ "$got" = "--baseline --branches " ]
t $? "option names still complete ($got)"
nkeys=$("$ACBB" keys | grep -c '^[a-z_0-9]*\.[A-Za-z_0-9]* = ')
got=$(comp "acbb run mine.ini --set " | wc -w)
[ "$nkeys" -gt 100 ] && [ "$got" -eq "$nkeys" ]
t $? "--set offers every key acbb keys lists ($got of $nkeys)"

# PRESET - : stdin (issue 28 item 12)
"$ACBB" run presets/7008C.ini --json 2>/dev/null | grep -v '"wall_ms"' >"$TMP/file.json"
"$ACBB" run - --json <presets/7008C.ini 2>/dev/null | grep -v '"wall_ms"' >"$TMP/stdin.json"
[ -s "$TMP/file.json" ] && cmp -s "$TMP/file.json" "$TMP/stdin.json"
t $? "acbb run - reads the preset from stdin: the file's document"
printf '[operating]\naxial_load_N = -4\n' | "$ACBB" check - >/dev/null 2>"$TMP/err"
code $? 2 "check - of a bad preset on stdin exits 2"
has "$TMP/err" "<stdin>:2: operating.axial_load_N = -4: must be >= 0 N" "naming <stdin> and the line"

tap_done
