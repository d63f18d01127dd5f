#!/bin/sh
# Issue 29 items 4 and 5 (TAP, tmux, 80x24, NO_COLOR): every series of a
# chart stays visible where curves share cells (the & mark, named in the
# legend), the Set screen's legend names every bearing at 80 columns with
# the marks the chart draws, and the title bar says which bearing of a set
# the screens show.
# Usage: test_tui_chart.sh PATH/TO/acbb   (cwd = repo root)
set -u
. "$(dirname "$0")/test_tui_lib.sh"

# The rows of the chart whose title row starts with $1, up to its x axis.
chart_rows() { screen | awk -v t="$1" 'index($0, t) == 1 { on = 1; next } on && / s$/ { exit } on'; }

cp "$ROOT/presets/7008C.ini" "$TMP/copy.ini"
TUI_ARGS="--pace 0" start "env NO_COLOR=1" ch1 copy.ini
wait_for "Idle at ambient"
keys r
wait_for "100% done"
plot=$(chart_rows "Temperature [C]" | cut -c6-) # less the y labels ("40 C ")
legend=$(screen | grep "^Temperature \[C\]")
echo "$plot" | grep -q "[o&]" && echo "$plot" | grep -q "[+&]" && echo "$plot" | grep -q "[x&]"
ok $? "Run chart at 80x24: outer ring (o), inner ring (+) and ball (x) each drawn or marked shared (&)"
! echo "$plot" | grep -q "&" || echo "$legend" | grep -q "&& both"
ok $? "the shared mark is named in the legend ($legend)"
echo "$legend" | grep -q "oo outer ring" && echo "$legend" | grep -q "++ inner ring" &&
    echo "$legend" | grep -q "xx ball"
ok $? "the legend names the three series with their marks"
keys q
wait_file "$TMP/ch1"

cp "$ROOT/presets/pair-DB-heated.ini" "$TMP/pair.ini"
TUI_ARGS="--pace 0" start "env NO_COLOR=1" ch2 pair.ini
wait_for "pair.ini"
keys r
wait_for "100% done"
wait_for "pair.ini bearing 0/2"
ok $? "the title bar says which bearing of the set the screens show"
keys S
wait_for "Outer rings [C]"
legend=$(screen | sed -n 's/.*\(Outer rings \[C\].*\)/\1/p')
echo "$legend" | grep -q "bearing o 0 + 1" || echo "$legend" | grep -q "oo bearing 0  ++ bearing 1"
ok $? "Set screen at 80 columns: the legend names both bearings ($legend)"
plot=$(chart_rows "Set preload [N]" | cut -c46-80) # the right-hand chart, less its y labels
# The two bearings' outer rings run alike in this DB pair: the chart then
# draws & and the legend says so; otherwise each bearing's own mark.
if echo "$plot" | grep -q "&"; then echo "$legend" | grep -q "& both"; else
    echo "$plot" | grep -q "o" && echo "$plot" | grep -q "+"; fi
ok $? "and the marks drawn are those the legend names"
keys ']'
wait_for "pair.ini bearing 1/2"
ok $? "] chooses bearing 1, and the title bar says so"
keys q
wait_file "$TMP/ch2"
echo "1..$n"
[ $failed -eq 0 ]
