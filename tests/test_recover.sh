#!/usr/bin/env bash
# Recovery files that cannot be turned against the user (issue 20 item 6),
# TAP through tmux (test_tui_lib.sh): an untrusted state directory is
# refused loudly, a planted symlink is replaced not followed, a planted
# file is not offered, names do not collide, undone edits leave no stale
# offer. $1 = the acbb binary.
. "$(dirname "$0")/test_tui_lib.sh"

STATE=$TMP/state
DIR=$STATE/acbb/recover
cp "$ROOT/presets/7008C.ini" "$TMP/mine.ini"
acbb_pid() { pgrep -P "$($T list-panes -t "$S" -F '#{pane_pid}')" -f "tui"; }
recfiles() { find "$DIR" -maxdepth 1 -name '*.ini' 2>/dev/null | sort; }
# Start on $1, make one unsaved edit (axial load $2); $3 = session name.
edit_one() {
    start "XDG_STATE_HOME='$STATE'" "$3" "$1"
    wait_for "${1##*/}"
    keys 5
    wait_for "pitch_diameter_mm"
    goto_field operating.axial_load_N
    keys Enter C-u "$2" Enter
    wait_for "${1##*/}*"
}
hup() { kill -HUP "$(acbb_pid)"; wait_file "$TMP/$1"; }

# 1. A recovery file, named after the preset and a hash of its real path.
edit_one mine.ini 750 r1
hup r1
f=$(recfiles)
case ${f##*/} in mine.ini-[0-9a-f]*.ini) [ "$(wc -l <<<"$f")" -eq 1 ] ;; *) false ;; esac
ok $? "SIGHUP keeps the edit in $DIR/${f##*/}"
[ "$(stat -c %a "$DIR")" = 700 ] && [ "$(stat -c %a "$f")" = 600 ]
ok $? "the directory is 0700, the file 0600"

# 2. A symlink planted at that name is replaced, its target untouched.
echo "precious" >"$TMP/victim"
rm -f "$f" && ln -s "$TMP/victim" "$f"
edit_one mine.ini 760 r2
keys n # no offer expected (a symlink is not offered); harmless otherwise
hup r2
[ "$(cat "$TMP/victim")" = precious ] && [ -f "$f" ] && [ ! -L "$f" ] && grep -q '^axial_load_N = 760$' "$f"
ok $? "a planted symlink is replaced by the recovery file, not followed (victim intact)"

# 3. A recovery file others may write is not offered.
chmod 666 "$f"
start "XDG_STATE_HOME='$STATE'" r3 mine.ini
wait_for "opened"
! screen | grep -q "from an earlier session"
ok $? "a group/other-writable recovery file is not offered"
keys q
wait_file "$TMP/r3"
chmod 600 "$f"

# 4. Names do not collide: b/c.ini and b%c.ini.
mkdir -p "$TMP/b"
cp "$ROOT/presets/7008C.ini" "$TMP/b/c.ini"
cp "$ROOT/presets/7008C.ini" "$TMP/b%c.ini"
rm -rf "$STATE"
edit_one b/c.ini 710 r4
hup r4
edit_one 'b%c.ini' 720 r5
hup r5
[ "$(recfiles | wc -l)" -eq 2 ] && grep -l '^axial_load_N = 710$' $(recfiles) >/dev/null &&
    grep -l '^axial_load_N = 720$' $(recfiles) >/dev/null
ok $? "b/c.ini and b%c.ini keep two recovery files"

# 5. Undone edits: the recovery file goes, nothing is offered next time.
rm -rf "$STATE"
edit_one mine.ini 730 r6
have_rec() { [ -n "$(recfiles)" ]; }
no_rec() { [ -z "$(recfiles)" ]; }
wait_until have_rec # the periodic write (every 5 s)
keys u
wait_until no_rec
ok $? "undoing back to the file removes the recovery file"
keys q
wait_file "$TMP/r6"
start "XDG_STATE_HOME='$STATE'" r7 mine.ini
wait_for "opened"
! screen | grep -q "from an earlier session"
ok $? "no stale offer after undone edits"
keys q
wait_file "$TMP/r7"

# 6. A state directory others may write: refused, and said loudly on SIGHUP.
rm -rf "$STATE"
mkdir -p "$DIR"
chmod 777 "$DIR"
edit_one mine.ini 740 r8
hup r8
wait_for "UNSAVED EDITS OF mine.ini ARE LOST"
ok $? "SIGHUP with an untrusted state directory says the edits are lost"
screen | grep -q "only you may write"
ok $? "... and why, naming the directory"
[ -z "$(recfiles)" ]
ok $? "nothing written into that directory"

echo "1..$n"
[ "$failed" -eq 0 ]
