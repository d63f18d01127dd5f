#!/bin/sh
# Nothing mixed (issue 20 items 3, 4, 7, 10), TAP: `acbb merge` and a
# resumed sweep refuse outputs of another scene, grid, run mode or record
# format, naming the keys that differ; indices must be whole and in range,
# grid values those of the index, CSV fields finite like JSONL; a merge of
# no records and a FIFO input neither crash nor hang.
# $1 = the acbb binary; cwd = repository root. Needs jq.
set -u
ACBB=${1:?usage: test_merge.sh path/to/acbb}
PRESET=presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-merge.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

G="--set fidelity.model=quasi-static --grid operating.axial_load_N=100,200 --grid operating.inner_speed_rpm=1000,2000"
# shellcheck disable=SC2086
sweep() { "$ACBB" sweep "$PRESET" $G "$@" >/dev/null 2>>"$TMP/log"; }
sweep --jsonl "$TMP/a.jsonl" --csv "$TMP/a.csv" --jobs 1
sweep --jsonl "$TMP/s1.jsonl" --csv "$TMP/s1.csv" --shard 1/2
head -1 "$TMP/a.jsonl" | jq -e '.acbb_sweep.format == 4 and (.acbb_sweep.fingerprint | length == 16)
    and .acbb_sweep.scene["operating.radial_load_N"] == "0"
    and (.acbb_sweep.scene | has("operating.axial_load_N") | not)' >/dev/null 2>&1
t $? "the header: format 4, a 16-digit fingerprint, every scene key the grid does not vary"
fp=$(head -1 "$TMP/a.jsonl" | jq -r .acbb_sweep.fingerprint)
jq -s -e --arg fp "$fp" '.[1:] | length == 4 and all(.[]; .fingerprint == $fp)' "$TMP/a.jsonl" >/dev/null 2>&1 &&
    [ "$(awk -F, -v fp="$fp" 'NR > 1 && $2 != fp { bad = 1 } END { print bad + 0 }' "$TMP/a.csv")" = 0 ]
t $? "every JSONL and CSV record carries the header's fingerprint"

# Another preset value, another --set, another grid, another mode.
# shellcheck disable=SC2086
"$ACBB" sweep presets/combined-load.ini $G --jsonl "$TMP/p.jsonl" --shard 2/2 >/dev/null 2>&1
# shellcheck disable=SC2086
"$ACBB" sweep "$PRESET" $G --set operating.radial_load_N=7 --jsonl "$TMP/r.jsonl" --shard 2/2 >/dev/null 2>&1
"$ACBB" sweep "$PRESET" --set fidelity.model=quasi-static --grid operating.axial_load_N=100,300 \
    --grid operating.inner_speed_rpm=1000,2000 --jsonl "$TMP/g.jsonl" --shard 2/2 >/dev/null 2>&1
sweep --transient --jsonl "$TMP/t.jsonl" --shard 2/2
"$ACBB" merge "$TMP/o" "$TMP/s1.jsonl" "$TMP/r.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses shards of another --set"
has "$TMP/err" 'operating.radial_load_N ("0" vs "7")' "... naming the key and both values"
"$ACBB" merge "$TMP/o" "$TMP/s1.jsonl" "$TMP/p.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses shards of another preset"
"$ACBB" merge "$TMP/o" "$TMP/s1.jsonl" "$TMP/g.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses shards of another grid"
has "$TMP/err" 'grid operating.axial_load_N (["100","200"] vs ["100","300"])' "... naming the grid key"
"$ACBB" merge "$TMP/o" "$TMP/s1.jsonl" "$TMP/t.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses a --transient shard with a steady one"
has "$TMP/err" 'mode ("steady" vs "transient")' "... naming the mode"
sed '1s/"format":4/"format":3/' "$TMP/a.jsonl" >"$TMP/v.jsonl"
"$ACBB" merge "$TMP/o" "$TMP/s1.jsonl" "$TMP/v.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses another record format"
tail -n +2 "$TMP/a.jsonl" >"$TMP/nohead.jsonl"
"$ACBB" merge "$TMP/o" "$TMP/nohead.jsonl" 2>"$TMP/err"
code $? 2 "merge refuses records without a header (an older format)"
has "$TMP/err" "no sweep header" "... and says so"
[ ! -e "$TMP/o" ]
t $? "a refused merge writes nothing"

# Records against their header.
bad_jsonl() { # sed-expression name
    sed "$1" "$TMP/a.jsonl" >"$TMP/b.jsonl"
    "$ACBB" merge "$TMP/o" "$TMP/b.jsonl" 2>"$TMP/err"
    code $? 2 "merge refuses a JSONL record with $2"
}
bad_jsonl 's/"index":1,/"index":1.5,/' 'index 1.5'
bad_jsonl 's/"index":1,/"index":4,/' 'index 4 of a 4-point grid'
bad_jsonl 's/"index":1,/"index":-1,/' 'index -1'
bad_jsonl '/"index":1,/s/"operating.inner_speed_rpm":2000/"operating.inner_speed_rpm":1000/' 'the grid values of another index'
bad_jsonl "3s/\"fingerprint\":\"$fp\"/\"fingerprint\":\"0000000000000000\"/" 'another fingerprint'
bad_jsonl '3s/"temperature_C.ball":[-0-9.e]*/"temperature_C.ball":1e999/' 'a number 1e999'
bad_csv() {
    sed "$1" "$TMP/a.csv" >"$TMP/b.csv"
    cp "$TMP/a.csv.json" "$TMP/b.csv.json" # its header: the records alone are refused
    "$ACBB" merge "$TMP/o" "$TMP/b.csv" 2>"$TMP/err"
    code $? 2 "merge refuses a CSV row with $2"
}
# column 7 is temperature_C.outer_ring (index, fingerprint, 2 grid keys, status, iterations)
for v in nan 1e999 hello inf; do
    bad_csv "3s/^\\(\\([^,]*,\\)\\{6\\}\\)[^,]*,/\\1$v,/" "temperature_C.outer_ring = $v"
done
bad_csv 's/^1,/1.5,/' 'index 1.5'
bad_csv '3s/,converged,/,converged,x,/' 'one field too many'
bad_csv '/^1,/s/^1,\([^,]*\),100,2000,/1,\1,200,2000,/' 'the grid values of another index'
"$ACBB" merge "$TMP/o" "$TMP/a.csv" 2>"$TMP/err"
code $? 0 "the untouched CSV merges"

# A resumed sweep refuses another scene, naming the key.
cp "$TMP/s1.jsonl" "$TMP/res.jsonl"
cp "$TMP/s1.csv" "$TMP/res.csv" && cp "$TMP/s1.csv.json" "$TMP/res.csv.json"
# shellcheck disable=SC2086
"$ACBB" sweep presets/combined-load.ini $G --jsonl "$TMP/res.jsonl" >/dev/null 2>"$TMP/err"
code $? 2 "resuming with another preset exits 2"
has "$TMP/err" "written by another sweep" "... saying so"
cmp -s "$TMP/res.jsonl" "$TMP/s1.jsonl"
t $? "... and leaves the file as it was"
# shellcheck disable=SC2086
"$ACBB" sweep "$PRESET" $G --set operating.radial_load_N=3 --csv "$TMP/res.csv" >/dev/null 2>"$TMP/err"
code $? 2 "resuming with another --set exits 2"
has "$TMP/err" 'operating.radial_load_N ("0" vs "3")' "... naming the key"
sweep --jsonl "$TMP/res.jsonl" --csv "$TMP/res.csv"
"$ACBB" merge "$TMP/m1.jsonl" "$TMP/res.jsonl" 2>>"$TMP/log" &&
    "$ACBB" merge "$TMP/m2.jsonl" "$TMP/a.jsonl" 2>>"$TMP/log" && cmp -s "$TMP/m1.jsonl" "$TMP/m2.jsonl"
t $? "the same sweep resumes and merges equal to the one-machine run"

# No records at all: a header-only shard merges (UBSan saw qsort(NULL, 0)).
sweep --jsonl "$TMP/e.jsonl" --max-points 0 --shard 1/1 2>/dev/null || head -1 "$TMP/a.jsonl" >"$TMP/e.jsonl"
head -1 "$TMP/a.jsonl" >"$TMP/e.jsonl"
"$ACBB" merge "$TMP/o.jsonl" "$TMP/e.jsonl" 2>"$TMP/err"
code $? 3 "a merge of a header and no records exits 3 (points missing; issue 28 item 9)"
[ "$(wc -l <"$TMP/o.jsonl")" -eq 1 ] && has "$TMP/err" "4 of the 4 points are missing" "... saying every point is missing"
: >"$TMP/empty.jsonl"
"$ACBB" merge "$TMP/o2.jsonl" "$TMP/empty.jsonl" 2>"$TMP/err"
code $? 2 "a merge of only empty files exits 2 (nothing to merge)"

# A FIFO input is refused at once, not read forever.
if mkfifo "$TMP/fifo" 2>/dev/null; then
    "$ACBB" merge "$TMP/o3.jsonl" "$TMP/fifo" 2>"$TMP/err"
    code $? 2 "merge refuses a FIFO input (no writer: would block)"
    has "$TMP/err" "not a regular file" "... saying why"
fi
tap_done
