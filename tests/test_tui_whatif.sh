#!/bin/sh
# Issue 29 item 1 (TAP, tmux, 80x24): the classroom what-if on 7008C. Pin
# the converged run as a baseline (m), change mounting.preload_N to 600 in
# the editor and apply (A): under the preset's force preload preload_N has
# no effect, so every change against the baseline is 0. The editor marks
# the key ('~' no effect, '!' changed and no effect) and its info rows say
# why and what makes it act; the Run
# screen says so next to the +0.00s instead of nothing.
# Usage: test_tui_whatif.sh PATH/TO/acbb   (cwd = repo root)
set -u
. "$(dirname "$0")/test_tui_lib.sh"

TUI_ARGS="--pace 0" start "env NO_COLOR=1" tw
wait_for "Idle at ambient"
keys r
wait_for "100% done"
keys m
wait_for "baseline pinned"
keys 5
wait_for "Enter edit"
keys / p r e l o a d _ N Enter
wait_for "mounting.preload_N:"
keys Enter C-u 600 Enter
wait_until sh -c "$T capture-pane -p -t $S | grep -q '^!mounting *preload_N'"
ok $? "the editor marks mounting.preload_N '!' (changed, and no effect in the scene as set)"
wait_for "NO EFFECT here: mounting.preload = force"
ok $? "its info rows say why: the axial load preloads a single bearing under a force preload"
wait_for "preload_N acts under"
ok $? "  and which key makes it act"
keys A 1
wait_for "note: mounting.preload_N has no effect here"
ok $? "the Run screen with a baseline pinned says the edit has no effect"
# The edit is unsaved (and the applied run may still go): q asks, y to
# each question. (Left unanswered, the wait for the exit took its whole
# 30 s bound in every run.)
keys q
quit_or_asked() { [ -s "$TMP/tw" ] || screen | grep -q "Quit anyway?\|Quit and lose it?"; }
for _ in 1 2; do
    wait_until quit_or_asked
    [ -s "$TMP/tw" ] || keys y
done
wait_file "$TMP/tw"
grep -q EXIT=0 "$TMP/tw"
ok $? "q, then y to its questions, quits with exit 0"
echo "1..$n"
[ $failed -eq 0 ]
