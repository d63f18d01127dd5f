#!/usr/bin/env bash
# Nothing typed is lost (issue "Nothing lost"): unsaved TUI edits reach a
# recovery file on SIGHUP, the next session offers them back, saving keeps
# the user's comments; Ctrl-\ restores the terminal. $1 = the acbb binary.
. "$(dirname "$0")/test_tui_lib.sh"

STATE=$TMP/state
printf '; my notes on this bearing\n[operating]\n; the load I test\naxial_load_N = 1000\n\n; speed\ninner_speed_rpm = 15000\n' \
    >"$TMP/mine.ini"
cp "$TMP/mine.ini" "$TMP/mine.orig"
acbb_pid() { pgrep -P "$($T list-panes -t "$S" -F '#{pane_pid}')" -f "tui"; }
recovery() { ls "$STATE"/acbb/recover/* 2>/dev/null | head -n 1; }

# 1. An edit, then the SSH link drops (SIGHUP).
start "XDG_STATE_HOME='$STATE'" rec1 mine.ini
wait_for "mine.ini"
keys 5
wait_for "pitch_diameter_mm"
goto_field operating.axial_load_N
keys Enter C-u 750 Enter
wait_for "mine.ini*"
ok $? "an edit marks the preset modified"
kill -HUP "$(acbb_pid)"
wait_file "$TMP/rec1" 5
grep -q 'EXIT=129' "$TMP/rec1"
ok $? "SIGHUP ends the TUI ($(cat "$TMP/rec1" 2>/dev/null))"
grep -q 'icanon' "$TMP/stty.rec1" && ! grep -q -- '-icanon' "$TMP/stty.rec1"
ok $? "the terminal is restored after SIGHUP (canonical mode back)"
f=$(recovery)
[ -n "$f" ] && grep -q '^axial_load_N = 750$' "$f"
ok $? "the unsaved edit is in the recovery file (${f##*/})"
cmp -s "$TMP/mine.ini" "$TMP/mine.orig"
ok $? "the preset itself is untouched"

# 2. The next session offers the edits back; saving keeps the comments.
start "XDG_STATE_HOME='$STATE'" rec2 mine.ini
wait_for "from an earlier session"
ok $? "reopening the preset offers the recovered edits"
keys y
wait_for "edits restored"
wait_for "mine.ini*"
ok $? "restored edits show as unsaved"
keys w
wait_for "saved mine.ini"
grep -q '^axial_load_N = 750' "$TMP/mine.ini" && grep -q '^; the load I test$' "$TMP/mine.ini" \
    && grep -q '^; my notes on this bearing$' "$TMP/mine.ini"
rc=$?
ok $rc "saved: the new value, and the user's comments kept"
[ $rc -eq 0 ] || sed 's/^/#   /' "$TMP/mine.ini"
[ "$(diff "$TMP/mine.orig" "$TMP/mine.ini" | grep -c '^[<>]')" = 2 ]
ok $? "saving rewrote exactly one line"
[ -z "$(recovery)" ]
ok $? "saving removes the recovery file"
keys q
wait_file "$TMP/rec2" 5

# 3. Ctrl-\ (SIGQUIT) leaves no alternate screen and a sane terminal.
start "XDG_STATE_HOME='$STATE'" rec3 mine.ini
wait_for "mine.ini"
keys 'C-\'
wait_file "$TMP/rec3" 5
grep -q 'EXIT=131' "$TMP/rec3"
ok $? "Ctrl-\\ ends the TUI ($(cat "$TMP/rec3" 2>/dev/null))"
[ "$($T display -p -t "$S" '#{alternate_on}')" = 0 ]
ok $? "no alternate screen left behind"
grep -q 'icanon' "$TMP/stty.rec3" && ! grep -q -- '-icanon' "$TMP/stty.rec3"
ok $? "the terminal is restored after Ctrl-\\"

# 4. A second Ctrl-C at the "unsaved edits" question leaves, and keeps them.
rm -rf "$STATE"
start "XDG_STATE_HOME='$STATE'" rec5 mine.ini
wait_for "mine.ini"
keys 5
wait_for "pitch_diameter_mm"
goto_field operating.axial_load_N
keys Enter C-u 640 Enter
wait_for "mine.ini*"
keys C-c
wait_for "Quit anyway?"
keys C-c
wait_file "$TMP/rec5" 5
f=$(recovery)
[ -n "$f" ] && grep -q '^axial_load_N = 640$' "$f"
ok $? "a second Ctrl-C at the unsaved-edits question keeps the edits in the recovery file"

# 5. The preset browser shows what each teaching scene is for.
cp -r "$ROOT/presets" "$TMP/presets"
start "XDG_STATE_HOME='$STATE'" rec4 mine.ini
wait_for "mine.ini"
keys 5 o
wait_for "Open a preset"
ok $? "o opens the preset browser"
keys j
wait_for "Look at:"
ok $? "the selected preset's 'Look at' text is shown"
screen | grep -q "Expect: converged"
ok $? "and the status its run ends with"
keys Escape q
wait_file "$TMP/rec4" 5

echo "1..$n"
[ "$failed" -eq 0 ]
