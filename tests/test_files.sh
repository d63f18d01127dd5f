#!/usr/bin/env bash
# Writes never destroy (issue "Nothing lost"): every file acbb writes goes
# through one atomic path (src/base/outfile.c); plots reach gnuplot with no file
# name in its script. $1 = the acbb binary.
. "$(dirname "$0")/tap.sh"
ACBB=$1
PRESET=$PWD/presets/7008C.ini
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1

# 1. A name with '' reaches the file system as typed; nothing else is written.
"$ACBB" plot "$PRESET" --kind losses --out "data''.svg" >/dev/null 2>"$TMP/err"
code $? 0 "plot to a name with doubled quotes exits 0"
[ -s "data''.svg" ] && [ ! -e "data'" ] && [ ! -e "data" ]
t $? "the plot is data''.svg and no stray file data' appears"
grep -q '</svg>' "data''.svg"
t $? "and it is a complete SVG"

# 2. A symlink is followed: the link stays, its target gets the new content.
echo old >target.csv
ln -s target.csv link.csv
"$ACBB" run "$PRESET" --csv link.csv --quiet 2>"$TMP/err"
code $? 0 "csv onto a symlink exits 0"
[ -L link.csv ] && head -n 1 target.csv | grep -q '^iteration,'
t $? "the symlink is still a link and its target holds the CSV"

# 3. A FIFO is written, never replaced.
mkfifo pipe.csv
cat pipe.csv >fifo.out &
reader=$!
# The background reader opens the FIFO some time after it starts; until
# then acbb refuses at once (no reader: exit 2, before anything runs), so
# poll by trying again (bounded) until the reader is there.
for _ in $(seq 300); do
    "$ACBB" run "$PRESET" --csv pipe.csv --quiet 2>"$TMP/err"
    rc=$?
    [ "$rc" -eq 2 ] && grep -q "a FIFO with no reader" "$TMP/err" || break
    sleep 0.1
done
code $rc 0 "csv onto a FIFO exits 0"
wait $reader
[ -p pipe.csv ] && head -n 1 fifo.out | grep -q '^iteration,'
t $? "the FIFO is still a FIFO and the reader got the CSV"

# 4. A device that fails writes: a clear error, the device untouched.
"$ACBB" run "$PRESET" --csv /dev/full --quiet 2>"$TMP/err"
code $? 4 "csv onto /dev/full: exit 4 (write failed after open)"
[ -c /dev/full ]
t $? "/dev/full is still a character device"
"$ACBB" report "$PRESET" --md /dev/full >/dev/null 2>"$TMP/err"
code $? 4 "report --md onto /dev/full: exit 4, the same rule"
"$ACBB" run "$PRESET" --csv "$TMP/no/such/dir/x.csv" --quiet 2>"$TMP/err"
code $? 2 "csv into a missing directory: exit 2 (bad path)"

# 5. Modes: a new file gets 0666 & ~umask (0644 under umask 022, not
#    mkstemp's 0600), an old one keeps its own. tests/test_outfile.c covers
#    other umasks and every way of naming the temp file.
umask 022
"$ACBB" report "$PRESET" --md new.md >/dev/null 2>"$TMP/err"
[ "$(stat -c %a new.md)" = 644 ]
t $? "report --md writes a new file with mode 644 (got $(stat -c %a new.md))"
echo old >kept.csv
chmod 640 kept.csv
"$ACBB" run "$PRESET" --csv kept.csv --quiet 2>"$TMP/err"
[ "$(stat -c %a kept.csv)" = 640 ] && head -n 1 kept.csv | grep -q '^iteration,'
t $? "an existing file keeps its mode 640 when rewritten"

# 6. A truncated image (a full disk mid-write; gnuplot still exits 0) never
#    replaces the old good plot. The fake gnuplot writes half a PNG.
printf '#!/bin/sh\ncat >/dev/null\nprintf "\\211PNG\\r\\n\\032\\nhalf"\nexit 0\n' >fakegp
chmod +x fakegp
echo "good old picture" >old.png
ACBB_GNUPLOT=$TMP/fakegp "$ACBB" run "$PRESET" --plot old.png --quiet 2>"$TMP/err"
rc=$?
[ $rc -eq 4 ] && grep -qx "good old picture" old.png
t $? "truncated PNG: exit 4 ($rc) and the old file is kept"
has "$TMP/err" "old.png" "the message names the file that was not written"

# 7. Nothing is left behind by any of the writes above.
[ -z "$(ls -A | grep 'acbb-\|\.tmp')" ]
t $? "no temporary files left in the directory"

tap_done
