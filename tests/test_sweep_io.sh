#!/bin/sh
# Sweep files that survive their writers (issue 26 items 2-4, 11; issue 28
# item 9), TAP: one sweep per output file (a second is refused, the first
# file intact); a failed write (a file over `ulimit -f`, as a full disk)
# leaves whole records that resume to the uninterrupted result; a header
# cut short resumes; sweeps differing only in [schedule] never mix; the
# wall-clock bound is no part of a sweep (resumes with another bound, its
# wall_limit points run again); a closed stdout pipe and a typo are exit
# codes with a message; merge exits 3 on missing points and refuses a
# shard as OUT. $1 = the acbb binary; cwd = repository root. Needs jq.
set -u
ACBB=${1:?usage: test_sweep_io.sh path/to/acbb}
PRESET=presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-sweepio.XXXXXX") || exit 1
BG=
trap '[ -n "$BG" ] && kill "$BG" 2>/dev/null; rm -rf "$TMP"' EXIT INT TERM
XDG_CONFIG_HOME="$TMP/xdg"
export XDG_CONFIG_HOME
. "$(dirname "$0")/tap.sh"

# 2 x 4 = 8 quasi-static points (milliseconds each).
G="--set fidelity.model=quasi-static --grid operating.axial_load_N=200,800
 --grid operating.inner_speed_rpm=4000:16000:4"
# shellcheck disable=SC2086
sweep() { "$ACBB" sweep "$PRESET" $G "$@"; }
sweep --jsonl "$TMP/one.jsonl" --csv "$TMP/one.csv" 2>"$TMP/err"
code $? 0 "the uninterrupted 8-point sweep"
"$ACBB" merge "$TMP/canon.jsonl" "$TMP/one.jsonl" 2>>"$TMP/log" &&
    "$ACBB" merge "$TMP/canon.csv" "$TMP/one.csv" 2>>"$TMP/log"
t $? "its canonical forms"

# ---- one writer per file (item 3) ----
# A long sweep (100000 points on one worker) holds big.jsonl; once its
# header is there a second sweep on the file is refused.
"$ACBB" sweep "$PRESET" --set fidelity.model=quasi-static --grid operating.axial_load_N=1:1000:100000 \
    --jobs 1 --jsonl "$TMP/big.jsonl" >/dev/null 2>"$TMP/bigerr" &
BG=$!
until [ -s "$TMP/big.jsonl" ] || ! kill -0 "$BG" 2>/dev/null; do :; done
# (--max-points 1: without the lock it would append one point and end)
"$ACBB" sweep "$PRESET" --set fidelity.model=quasi-static --grid operating.axial_load_N=1:1000:100000 \
    --jobs 1 --max-points 1 --jsonl "$TMP/big.jsonl" >/dev/null 2>"$TMP/err"
code $? 2 "a second sweep on a file another sweep writes exits 2"
has "$TMP/err" "big.jsonl: another sweep is writing this file" "... naming the file and why"
kill -0 "$BG" 2>/dev/null
t $? "... while the first still runs"
kill -TERM "$BG"
wait "$BG"
code $? 3 "the first, stopped by SIGTERM, exits 3 (cancelled)"
BG=
nbig=$(($(wc -l <"$TMP/big.jsonl") - 1))
"$ACBB" merge "$TMP/bigm.jsonl" "$TMP/big.jsonl" 2>"$TMP/err"
code $? 3 "its file merges (every line a whole record of that sweep; points missing: 3)"
[ "$(($(wc -l <"$TMP/bigm.jsonl") - 1))" -eq "$nbig" ] && [ "$(grep -c acbb_sweep "$TMP/big.jsonl")" -eq 1 ]
t $? "... all $nbig records kept, one header: nothing of the second sweep in it"
# Shards write different files side by side.
sweep --shard 1/2 --jsonl "$TMP/s1.jsonl" 2>>"$TMP/log" &
p1=$!
sweep --shard 2/2 --jsonl "$TMP/s2.jsonl" 2>>"$TMP/log"
r2=$?
wait "$p1"
r1=$?
[ "$r1" -eq 0 ] && [ "$r2" -eq 0 ] && "$ACBB" merge "$TMP/sh.jsonl" "$TMP/s1.jsonl" "$TMP/s2.jsonl" 2>>"$TMP/log" &&
    cmp -s "$TMP/sh.jsonl" "$TMP/canon.jsonl"
t $? "two shards at once, two files: both run, merged == canonical"

# ---- a failed write leaves whole records (item 4) ----
# ulimit -f makes a write past N blocks fail with EFBIG, as a full disk
# fails with ENOSPC; the block size of ulimit -f differs between shells.
(ulimit -f 1 && head -c 4096 /dev/zero >"$TMP/blk") 2>/dev/null
BLK=$(wc -c <"$TMP/blk")
for f in jsonl csv; do
    hl=1; [ $f = csv ] && hl=2
    lim=$(($(head -n $((hl + 3)) "$TMP/one.$f" | wc -c) / BLK)) # within the 3rd record
    (ulimit -f "$lim" && sweep --$f "$TMP/full.$f" --jobs 1) >/dev/null 2>"$TMP/err"
    code $? 4 "$f: a write past the file size limit exits 4"
    has "$TMP/err" "cannot write $TMP/full.$f: File too large; the file ends with its last whole record" \
        "... naming the file, the error and what is kept"
    [ "$(tail -c 1 "$TMP/full.$f" | od -An -c | tr -d ' ')" = '\n' ] && [ "$(wc -c <"$TMP/full.$f")" -le $((lim * BLK)) ]
    t $? "... the file ends with a whole line, within the limit"
    kept=$(($(wc -l <"$TMP/full.$f") - hl))
    [ "$kept" -ge 1 ] && [ "$kept" -lt 8 ]
    t $? "... $kept of the 8 records written before the failure"
    sweep --$f "$TMP/full.$f" 2>"$TMP/err"
    code $? 0 "$f: the same command with room resumes"
    "$ACBB" merge "$TMP/fullm.$f" "$TMP/full.$f" 2>>"$TMP/log" && cmp -s "$TMP/fullm.$f" "$TMP/canon.$f"
    t $? "$f: ... and equals the uninterrupted sweep (canonical form)"
done

# ---- a header cut short (a kill while it was written) ----
# Cut inside the CSV column line (the header crossing a 4 KiB stdio
# buffer left line 1 whole), inside line 1 (at 4096), inside the JSONL header.
l1=$(head -1 "$TMP/one.csv" | wc -c)
for cut in csv:$((l1 + 40)) csv:4096 jsonl:4096 jsonl:100; do
    f=${cut%%:*} at=${cut#*:}
    head -c "$at" "$TMP/one.$f" >"$TMP/cut.$f"
    sweep --$f "$TMP/cut.$f" 2>"$TMP/err"
    code $? 0 "$f header cut at byte $at: the sweep resumes (no records yet: header written again)"
    "$ACBB" merge "$TMP/cutm.$f" "$TMP/cut.$f" 2>>"$TMP/log" && cmp -s "$TMP/cutm.$f" "$TMP/canon.$f"
    t $? "... and equals the uninterrupted sweep"
done
printf 'my notes, no newline' >"$TMP/notes.jsonl"
sweep --jsonl "$TMP/notes.jsonl" 2>"$TMP/err"
code $? 2 "an unfinished first line that is not this sweep's header is refused"
[ "$(cat "$TMP/notes.jsonl")" = "my notes, no newline" ]
t $? "... and the file is left as it was"

# ---- sweeps differing only in [schedule] never mix (item 2) ----
SCHED='schedule.rows=0, 16000, 1000, 0'
sweep --shard 1/2 --set "$SCHED" --jsonl "$TMP/sch1.jsonl" 2>>"$TMP/log"
head -1 "$TMP/sch1.jsonl" | jq -e '.acbb_sweep.format == 4 and
    .acbb_sweep.scene["schedule.rows"] == "0, 16000, 1000, 0"' >/dev/null 2>&1 &&
    head -1 "$TMP/s1.jsonl" | jq -e '.acbb_sweep.scene["schedule.rows"] == ""' >/dev/null 2>&1
t $? "the header lists the schedule's rows (\"\" without)"
"$ACBB" merge "$TMP/o.jsonl" "$TMP/s2.jsonl" "$TMP/sch1.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses shards whose presets differ only in [schedule]"
has "$TMP/err" 'schedule.rows ("" vs "0, 16000, 1000, 0")' "... naming the rows"
cp "$TMP/s1.jsonl" "$TMP/r.jsonl"
sweep --set "$SCHED" --jsonl "$TMP/r.jsonl" 2>"$TMP/err"
code $? 2 "resume refuses a file of the sweep without the schedule"
cmp -s "$TMP/r.jsonl" "$TMP/s1.jsonl"
t $? "... and leaves it as it was"

# ---- the wall-clock bound is no part of a sweep (item 11) ----
sweep --max-wall 600 --max-points 3 --jsonl "$TMP/mw.jsonl" 2>>"$TMP/log"
sweep --max-wall 900 --jsonl "$TMP/mw.jsonl" 2>"$TMP/err"
code $? 0 "a sweep resumes with a larger --max-wall"
"$ACBB" merge "$TMP/mwm.jsonl" "$TMP/mw.jsonl" 2>>"$TMP/log" && cmp -s "$TMP/mwm.jsonl" "$TMP/canon.jsonl"
t $? "... equal to the sweep without a bound"
sweep --max-wall 0.000001 --jsonl "$TMP/wl.jsonl" 2>>"$TMP/log"
jq -s -e '.[1:] | length == 8 and all(.[]; .status == "wall_limit")' "$TMP/wl.jsonl" >/dev/null 2>&1
t $? "a 1 us bound: every point wall_limit"
sweep --jsonl "$TMP/wl.jsonl" 2>"$TMP/err"
code $? 0 "resumed without the bound: the wall_limit points run again"
"$ACBB" merge "$TMP/wlm.jsonl" "$TMP/wl.jsonl" 2>>"$TMP/log" && cmp -s "$TMP/wlm.jsonl" "$TMP/canon.jsonl"
t $? "... merge keeps their results over the wall_limit records: == uninterrupted"
"$ACBB" merge "$TMP/wlm2.jsonl" "$TMP/wl.jsonl" "$TMP/one.jsonl" 2>>"$TMP/log" &&
    cmp -s "$TMP/wlm2.jsonl" "$TMP/canon.jsonl"
t $? "... whatever the order of the inputs"

# ---- a closed stdout pipe (item 11) ----
# 100 records (about 120 kB) cannot all wait in a pipe whose reader has
# gone (64 kB), so a write fails with EPIPE whatever the timing.
{ "$ACBB" sweep "$PRESET" --set fidelity.model=quasi-static --grid operating.axial_load_N=100:1000:100 \
    2>"$TMP/err"; echo $? >"$TMP/rc"; } | true
code "$(cat "$TMP/rc")" 4 "a sweep to a closed pipe exits 4, not 141 (SIGPIPE)"
has "$TMP/err" "cannot write standard output: Broken pipe" "... saying so"

# ---- merge: missing points, a shard as OUT (issue 28 item 9) ----
"$ACBB" merge "$TMP/half.jsonl" "$TMP/s1.jsonl" 2>"$TMP/err"
code $? 3 "merge with points missing exits 3"
has "$TMP/err" "4 of the 8 points are missing (index 1, 3, 5, 7)" "... naming how many and which"
[ "$(wc -l <"$TMP/half.jsonl")" -eq 5 ]
t $? "... and still writes the 4 it has"
cp "$TMP/s1.jsonl" "$TMP/keep.jsonl"
"$ACBB" merge "$TMP/s1.jsonl" "$TMP/s2.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses an existing shard as OUT (OUT forgotten)"
has "$TMP/err" "is a sweep's own output" "... saying so"
cmp -s "$TMP/s1.jsonl" "$TMP/keep.jsonl"
t $? "... and the shard is untouched"
sweep --shard 1/2 --csv "$TMP/c1.csv" 2>>"$TMP/log"
sweep --shard 2/2 --csv "$TMP/c2.csv" 2>>"$TMP/log"
"$ACBB" merge "$TMP/c1.csv" "$TMP/c2.csv" 2>"$TMP/err"
code $? 2 "... a CSV shard too"
"$ACBB" merge "$TMP/half.jsonl" "$TMP/s1.jsonl" "$TMP/s2.jsonl" 2>"$TMP/err"
code $? 0 "an earlier merge's output may be merged over"
cmp -s "$TMP/half.jsonl" "$TMP/canon.jsonl"
t $? "... giving the canonical form"

tap_done
