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
# csvh: a CSV with its header on a first line (--csv-header; the form
# before issue 28 item 8), csv: plain, its header in the sidecar FILE.json
sweep --csv-header --csv "$TMP/one.csvh" 2>>"$TMP/log"
code $? 0 "... and with --csv-header"
"$ACBB" merge "$TMP/canon.jsonl" "$TMP/one.jsonl" 2>>"$TMP/log" &&
    "$ACBB" merge "$TMP/canon.csv" "$TMP/one.csv" 2>>"$TMP/log" &&
    "$ACBB" merge "$TMP/canon.csvh" "$TMP/one.csvh" 2>>"$TMP/log"
t $? "its canonical forms"
# the option that writes format f to file $1
out() { case $f in csvh) echo "--csv-header --csv $1" ;; *) echo "--$f $1" ;; esac; }

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
for f in jsonl csvh; do
    hl=1; [ $f = csvh ] && hl=2
    lim=$(($(head -n $((hl + 3)) "$TMP/one.$f" | wc -c) / BLK)) # within the 3rd record
    # shellcheck disable=SC2046
    (ulimit -f "$lim" && sweep $(out "$TMP/full.$f") --jobs 1) >/dev/null 2>"$TMP/err"
    code $? 4 "$f: a write past the file size limit exits 4"
    has "$TMP/err" "cannot write $TMP/full.$f: File too large; the file ends with its last whole record" \
        "... naming the file, the error and what is kept"
    [ "$(tail -c 1 "$TMP/full.$f" | od -An -c | tr -d ' ')" = '\n' ] && [ "$(wc -c <"$TMP/full.$f")" -le $((lim * BLK)) ]
    t $? "... the file ends with a whole line, within the limit"
    kept=$(($(wc -l <"$TMP/full.$f") - hl))
    [ "$kept" -ge 1 ] && [ "$kept" -lt 8 ]
    t $? "... $kept of the 8 records written before the failure"
    # shellcheck disable=SC2046
    sweep $(out "$TMP/full.$f") 2>"$TMP/err"
    code $? 0 "$f: the same command with room resumes"
    "$ACBB" merge "$TMP/fullm.$f" "$TMP/full.$f" 2>>"$TMP/log" && cmp -s "$TMP/fullm.$f" "$TMP/canon.$f"
    t $? "$f: ... and equals the uninterrupted sweep (canonical form)"
done

# A plain CSV's sidecar is committed before the CSV's first byte: a write
# limit below the sidecar's size stops the sweep with an empty CSV, which
# the same command with room starts over.
(ulimit -f 1 && sweep --csv "$TMP/tiny.csv" --jobs 1) >/dev/null 2>"$TMP/err"
rc=$?
[ "$rc" -ne 0 ] && [ ! -s "$TMP/tiny.csv" ] && [ ! -e "$TMP/tiny.csv.json" ]
t $? "csv: a sidecar that cannot be written: exit $rc, no CSV bytes, no sidecar"
sweep --csv "$TMP/tiny.csv" 2>"$TMP/err" && "$ACBB" merge "$TMP/tinym.csv" "$TMP/tiny.csv" 2>>"$TMP/log" &&
    cmp -s "$TMP/tinym.csv" "$TMP/canon.csv"
t $? "... the same command with room runs it whole"

# ---- a header cut short (a kill while it was written) ----
# Cut inside the CSV column line (the header crossing a 4 KiB stdio
# buffer left line 1 whole), inside line 1 (at 4096), inside the JSONL
# header; a plain CSV inside its column line (its sidecar whole beside it).
l1=$(head -1 "$TMP/one.csvh" | wc -c)
cp "$TMP/one.csv.json" "$TMP/cut.csv.json"
for cut in csvh:$((l1 + 40)) csvh:4096 jsonl:4096 jsonl:100 csv:100; do
    f=${cut%%:*} at=${cut#*:}
    head -c "$at" "$TMP/one.$f" >"$TMP/cut.$f"
    # shellcheck disable=SC2046
    sweep $(out "$TMP/cut.$f") 2>"$TMP/err"
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

# ---- a plain CSV, its header beside it (issue 28 item 8) ----
head -1 "$TMP/one.csv" | grep -q '^index,fingerprint,operating.axial_load_N,operating.inner_speed_rpm,status,'
t $? "the CSV's first line is its column header (csv readers, pandas, spreadsheets take it as such)"
python3 -c 'import csv, sys; r = list(csv.DictReader(open(sys.argv[1])))
assert len(r) == 8 and all(x["status"] == "converged" and float(x["losses_W.total"]) > 0 for x in r)' "$TMP/one.csv"
t $? "... Python's csv reads 8 records by name"
[ "$(cat "$TMP/one.csv.json")" = "$(head -1 "$TMP/one.jsonl")" ]
t $? "the sidecar one.csv.json holds the header line of the JSONL"
[ "$(sed 1d "$TMP/canon.csv")" = "$(sed '1,2d' "$TMP/canon.csvh")" ] &&
    [ "$(head -1 "$TMP/canon.csvh")" = "# $(cat "$TMP/canon.csv.json")" ]
t $? "--csv-header: the same records, the header on a first line '# {...}' (merged: the same header)"
cp "$TMP/one.csv" "$TMP/noside.csv"
sweep --csv "$TMP/noside.csv" 2>"$TMP/err"
code $? 2 "a plain CSV without its sidecar is not resumed"
has "$TMP/err" "noside.csv: its header $TMP/noside.csv.json is missing" "... naming the missing file"
cmp -s "$TMP/noside.csv" "$TMP/one.csv"
t $? "... and the CSV is left as it was"
"$ACBB" merge "$TMP/nosidem.csv" "$TMP/noside.csv" 2>"$TMP/err"
code $? 2 "merge refuses a plain CSV without its sidecar"
has "$TMP/err" "noside.csv.json is missing" "... saying which file is missing"
cp "$TMP/one.csv" "$TMP/form.csv" && cp "$TMP/one.csv.json" "$TMP/form.csv.json"
sweep --csv-header --csv "$TMP/form.csv" 2>"$TMP/err"
code $? 2 "a plain CSV resumed with --csv-header is refused"
has "$TMP/err" "run the same command without --csv-header" "... saying what to do"
sweep --csv "$TMP/one.csvh" 2>"$TMP/err"
code $? 2 "a --csv-header CSV resumed without it is refused"
has "$TMP/err" "run the same command with --csv-header" "... saying what to do"
sweep --csv "$TMP/one.csv" 2>"$TMP/err"
code $? 0 "a plain CSV with its sidecar resumes (nothing left to run)"
[ "$(cat "$TMP/one.csv.json")" = "$(head -1 "$TMP/one.jsonl")" ]
t $? "... its sidecar unchanged"
sweep --shard 1/2 --csv "$TMP/p1.csv" 2>>"$TMP/log"
sweep --shard 2/2 --csv "$TMP/p2.csv" 2>>"$TMP/log"
"$ACBB" merge "$TMP/pm.csv" "$TMP/p2.csv" "$TMP/p1.csv" 2>>"$TMP/log" &&
    cmp -s "$TMP/pm.csv" "$TMP/canon.csv" && cmp -s "$TMP/pm.csv.json" "$TMP/canon.csv.json"
t $? "plain CSV shards merge into the canonical CSV and its sidecar"
sweep --jsonl "$TMP/same.csv.json" --csv "$TMP/same.csv" 2>"$TMP/err"
code $? 2 "--jsonl FILE.csv.json with --csv FILE.csv (the header file) is refused"
[ ! -e "$TMP/same.csv" ] && [ ! -e "$TMP/same.csv.json" ]; t $? "... before any file is made"

# ---- --metric: any acbb metrics path in the records (issue 28 item 8) ----
M="--metric life.Lnmr_h --metric balls[2].pmax_i_GPa --metric T_cavity_C"
# shellcheck disable=SC2086
sweep --max-points 1 $M --jsonl "$TMP/m.jsonl" 2>"$TMP/err"
code $? 2 "--metric of a fixed column (T_cavity_C = temperature_C.cavity) is refused"
has "$TMP/err" "--metric T_cavity_C: temperature_C.cavity is already in every record" "... naming it"
sweep --metric life.Lnmr --jsonl "$TMP/m.jsonl" 2>"$TMP/err"
code $? 2 "an unknown --metric is refused before anything runs"
[ ! -e "$TMP/m.jsonl" ]; t $? "... no file made"
M="--metric life_Lnmr_h --metric balls[2].pmax_i_GPa"
# shellcheck disable=SC2086
sweep $M --jsonl "$TMP/m.jsonl" --csv "$TMP/m.csv" 2>"$TMP/err"
code $? 0 "a sweep with --metric runs"
head -1 "$TMP/m.jsonl" | jq -e '.acbb_sweep.metrics == ["life.Lnmr_h", "balls[2].pmax_i_GPa"]' >/dev/null
t $? "the header lists the metrics, canonical (life_Lnmr_h is life.Lnmr_h)"
[ "$(head -1 "$TMP/m.jsonl" | jq -r .acbb_sweep.fingerprint)" != "$(head -1 "$TMP/one.jsonl" | jq -r .acbb_sweep.fingerprint)" ]
t $? "... and the fingerprint covers them"
"$ACBB" run "$PRESET" --set fidelity.model=quasi-static --set operating.axial_load_N=800 \
    --set operating.inner_speed_rpm=16000 --set fidelity.thermal_mode=steady --json >"$TMP/r.json" 2>/dev/null
jq -s -e --slurpfile r "$TMP/r.json" '.[1:][] | select(.index == 7)
    | .["life.Lnmr_h"] == $r[0].life.Lnmr_h and .["balls[2].pmax_i_GPa"] == $r[0].balls[2].pmax_i_GPa' \
    "$TMP/m.jsonl" >/dev/null
t $? "JSONL: point 7's metrics are the run JSON's (life.Lnmr_h, balls[2].pmax_i_GPa)"
python3 - "$TMP/m.csv" "$TMP/m.jsonl" <<'PY'
import csv, json, sys
rows = {r["index"]: r for r in csv.DictReader(open(sys.argv[1]))}
recs = [json.loads(x) for x in open(sys.argv[2])][1:]
assert list(rows["0"])[-4:] == ["life.Lnmr_h", "balls[2].pmax_i_GPa", "message", "wall_ms"]
for j in recs:
    for k in ("life.Lnmr_h", "balls[2].pmax_i_GPa"):
        assert float(rows[str(j["index"])][k]) == j[k], (k, j[k])
PY
t $? "CSV: the metric columns before message, the JSONL's doubles"
sweep --metric life.Lnmr_h --jsonl "$TMP/m.jsonl" 2>"$TMP/err"
code $? 2 "resuming with another --metric set is refused"
has "$TMP/err" 'Differs (file vs now): metrics (["life.Lnmr_h","balls[2].pmax_i_GPa"] vs ["life.Lnmr_h"])' \
    "... naming the metrics"
# shellcheck disable=SC2086
sweep $M --jsonl "$TMP/m.jsonl" --csv "$TMP/m.csv" 2>"$TMP/err"
code $? 0 "the same --metric set resumes"
"$ACBB" merge "$TMP/mm.csv" "$TMP/m.csv" 2>>"$TMP/log" && "$ACBB" merge "$TMP/mm.jsonl" "$TMP/m.jsonl" 2>>"$TMP/log" &&
    [ "$(wc -l <"$TMP/mm.csv")" -eq 9 ] && [ "$(wc -l <"$TMP/mm.jsonl")" -eq 9 ]
t $? "... and merges (8 records each)"

# ---- --no-stiffness: no probes, no stiffness columns (issue 30) ----
sweep --no-stiffness --jsonl "$TMP/ns.jsonl" --csv "$TMP/ns.csv" 2>"$TMP/err"
code $? 0 "a sweep with --no-stiffness runs"
head -1 "$TMP/ns.jsonl" | jq -e '.acbb_sweep.stiffness == false' >/dev/null &&
    jq -e '.acbb_sweep.stiffness == false' "$TMP/ns.csv.json" >/dev/null &&
    head -1 "$TMP/one.jsonl" | jq -e '.acbb_sweep | has("stiffness") | not' >/dev/null
t $? "the JSONL header and the CSV sidecar say \"stiffness\": false (a default sweep's has no such key)"
! grep -q stiffness "$TMP/ns.csv" && ! tail -n +2 "$TMP/ns.jsonl" | grep -q stiffness &&
    head -1 "$TMP/one.csv" | grep -q ring.stiffness_axial_N_per_um
t $? "no record and no column carries a stiffness (the default CSV has ring.stiffness_axial_N_per_um)"
python3 - "$TMP/ns.csv" "$TMP/one.csv" <<'PY'
import csv, sys
ns = {r["index"]: r for r in csv.DictReader(open(sys.argv[1]))}
one = {r["index"]: r for r in csv.DictReader(open(sys.argv[2]))}
assert len(ns) == 8
for i, r in ns.items():
    for k, v in r.items():
        if k not in ("fingerprint", "wall_ms"):
            assert v == one[i][k], (i, k, v, one[i][k])
PY
t $? "every other column equals the default sweep's, digit for digit (the probes change no state)"
[ "$(head -1 "$TMP/ns.jsonl" | jq -r .acbb_sweep.fingerprint)" != "$(head -1 "$TMP/one.jsonl" | jq -r .acbb_sweep.fingerprint)" ]
t $? "... the fingerprint differs (the records have other fields)"
sweep --jsonl "$TMP/ns.jsonl" 2>"$TMP/err"
code $? 2 "resuming a --no-stiffness output without it is refused"
has "$TMP/err" "Differs (file vs now): stiffness (false vs absent)" "... naming stiffness"
sweep --no-stiffness --jsonl "$TMP/ns.jsonl" --csv "$TMP/ns.csv" 2>"$TMP/err"
code $? 0 "the same command resumes (nothing left to run)"
"$ACBB" merge "$TMP/nsm.csv" "$TMP/ns.csv" 2>>"$TMP/log" && "$ACBB" merge "$TMP/nsm.jsonl" "$TMP/ns.jsonl" 2>>"$TMP/log" &&
    [ "$(wc -l <"$TMP/nsm.csv")" -eq 9 ] && ! grep -q stiffness "$TMP/nsm.csv"
t $? "... and merges (8 records, no stiffness column)"
sweep --no-stiffness --metric ring.stiffness_tilt_Nm_per_mrad --max-points 1 --jsonl "$TMP/nsx.jsonl" 2>"$TMP/err"
code $? 2 "--metric of a stiffness with --no-stiffness is refused"
has "$TMP/err" "--no-stiffness computes no stiffness" "... saying why"
"$ACBB" sweep --help >"$TMP/help" 2>&1
has "$TMP/help" "--no-stiffness" "sweep --help documents --no-stiffness"

tap_done
