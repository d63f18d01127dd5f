#!/bin/sh
# Exit codes as the README says, command by command and flag by flag
# (issue 20 item 9, issue 26 item 11), TAP, from one table checked against
# the README's: 0 done, 2 bad input (an output path that cannot be opened,
# an output over an input, two formats on one stream), 3 not converged (the
# wall-clock bound included), 4 a write that failed once open (/dev/full,
# a file-size limit) or stdout that cannot be written.
# Also: no inf/nan in text output, --quiet quiet, FIFOs never hang.
# $1 = the acbb binary; cwd = repository root.
set -u
ACBB=${1:?usage: test_exit_codes.sh path/to/acbb}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-exit.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
. "$(dirname "$0")/tap.sh"

P=presets/7008C.ini
Q="--set fidelity.model=quasi-static"
# The wall-clock bound's exit 3 (--max-wall) is asked of scenes it must
# stop on any machine: tests/unending.ini at 0.05 s (it cannot converge
# before millions of steps) and, at 1 ms, combined-load's dynamic set-up
# (hundreds of ms). 7008C at the dynamic level converges in 0.3 s of CPU
# and sets up in 20 ms: a machine a few times faster than this one ended
# the 0.05 s run converged (exit 0).
CL="presets/combined-load.ini --set fidelity.model=dynamic"
G="--grid operating.axial_load_N=100,200"
cp "$P" "$TMP/keep.ini"
"$ACBB" run "$P" $Q --json >"$TMP/base.json" 2>/dev/null
: >"$TMP/in.jsonl"
"$ACBB" sweep "$P" $Q $G --jsonl "$TMP/in.jsonl" >/dev/null 2>&1
head -n 2 "$TMP/in.jsonl" >"$TMP/part.jsonl" # the header and one of two points
echo "not json" >"$TMP/garbage.json"
NX=$TMP/no/such/dir
# issue 26: a dangling symlink's target is the file written; a name longer
# than the writer's temporary file leaves room for (NAME_MAX - 24).
ln -s dl-target.csv "$TMP/dl"
LONG=$TMP/$(printf 'x%.0s' $(seq 240)).csv
# 224 bytes: fits, but its sibling FILE-history-loads.png does not.
LONGP=$TMP/$(printf 'y%.0s' $(seq 220)).png
cp "$P" "$TMP/seed.ini"

# A full disk for one command: a file-size limit of one block makes every
# write of a preset fail (EFBIG, SIGXFSZ ignored); a short message on
# stderr still fits.
full() { sh -c 'trap "" XFSZ; ulimit -f 1; exec "$0" "$@"' "$ACBB" "$@"; }
cp "$P" "$TMP/wall.ini"
: >"$TMP/covered"

# want | arguments (word-split; no spaces inside one argument). The first
# word may say how it runs: STDOUT_FULL (stdout is /dev/full), FSIZE (the
# file-size limit above), NOGNUPLOT (PATH without gnuplot). Grouped by
# command, a case for every entry of the README's exit-code table (checked
# below against the table itself).
while IFS='|' read -r want args; do
    case $want in ''|'#'*) continue ;; esac
    # shellcheck disable=SC2086
    set -- $args
    how=$1
    case $how in STDOUT_FULL|FSIZE|NOGNUPLOT) shift ;; *) how= ;; esac
    case $how in
    STDOUT_FULL) timeout 120 "$ACBB" "$@" >/dev/full 2>"$TMP/err" </dev/null ;;
    FSIZE) full "$@" >"$TMP/out" 2>"$TMP/err" </dev/null ;;
    NOGNUPLOT) timeout 120 env PATH=/nonexistent "$ACBB" "$@" >"$TMP/out" 2>"$TMP/err" </dev/null ;;
    *) timeout 120 "$ACBB" "$@" >"$TMP/out" 2>"$TMP/err" </dev/null ;;
    esac
    rc=$?
    code $rc "$want" "acbb$args"
    # every nonzero exit says why (an "acbb: " line on stderr)
    if [ "$want" -ne 0 ] && [ "$rc" -eq "$want" ]; then
        grep -q '^acbb: ' "$TMP/err"
        t $? "... says why on stderr"
    fi
    cmd=$1
    [ "$1" = bench ] && cmd="$1 $2"
    [ "$rc" -eq "$want" ] && echo "$cmd|$want" >>"$TMP/covered"
done <<EOF_TABLE
# run
0| run $P $Q --quiet
2| run $P --josn
2| run $TMP/nosuch.ini
2| run $P --set operating.axial_load_N=-1
3| run $P $Q --set thermal.max_steps=2 --json
3| run tests/unending.ini --max-wall 0.05 --json
2| run $P --max-wall -1
2| run $P --max-wall soon
2| run $P $Q --csv $NX/x.csv
4| run $P $Q --csv /dev/full
4| STDOUT_FULL run $P $Q
4| NOGNUPLOT run $P $Q --plot $TMP/r.png
2| run $P $Q --plot $NX/x.png
2| run $P $Q --baseline $TMP/nosuch.json
2| run $P $Q --baseline $TMP/garbage.json
2| run $TMP/keep.ini $Q --csv $TMP/keep.ini
2| run $P $Q --csv - --json
2| run $P $Q --baseline $TMP/base.json --csv $TMP/base.json
2| run $P $Q --csv $LONG
2| run $P $Q --plot $LONGP
2| run $P $Q --plot $TMP/q.png --csv $TMP/q-losses.png
2| plot $P $Q --kind all --out $LONGP
# check
0| check $P
2| check $P --set bearing.n_balls=0
2| check $P --set bearing.cage_width_mm=1e-06
4| STDOUT_FULL check $P
# edit (seed.ini is never changed here: checked below)
2| edit $TMP/keep.ini
0| edit $TMP/keep.ini --set operating.radial_load_N=5
2| edit $TMP/seed.ini --set lubricant.grade=VG2
2| edit $TMP/seed.ini --set bearing.cage_width_mm=1e-06
2| edit $TMP/seed.ini --set operating.axial_load_N=5 --out $TMP/seed.ini
2| edit $TMP/seed.ini --set operating.axial_load_N=5 --out $LONG
0| edit $TMP/wall.ini --set fidelity.model=dynamic --set fidelity.max_wall_s=1e-06
4| FSIZE edit $TMP/seed.ini --set operating.axial_load_N=300
4| STDOUT_FULL edit $TMP/keep.ini --set operating.radial_load_N=6
# sweep
2| sweep $P $Q $G --jsonl $TMP/x --csv $TMP/x
2| sweep $P $Q $G --jsonl - --json
2| sweep $P $Q $G --jsonl $NX/x.jsonl
2| sweep $P $Q $G --csv $NX/x.csv
2| sweep $P $Q $G --jsonl $TMP/dl --csv $TMP/dl-target.csv
4| sweep $P $Q $G --jsonl /dev/full
4| sweep $P $Q $G --csv /dev/full
0| sweep $P $Q $G --jsonl $TMP/in.jsonl
3| sweep $P $Q $G --set thermal.max_steps=2 --jsonl $TMP/s3.jsonl
4| STDOUT_FULL sweep $P $Q --param operating.axial_load_N --values 100,200
# merge
2| merge $TMP/in.jsonl $TMP/in.jsonl
2| merge $NX/m.jsonl $TMP/in.jsonl
4| merge /dev/full $TMP/in.jsonl
0| merge $TMP/m.jsonl $TMP/in.jsonl
3| merge $TMP/m3.jsonl $TMP/part.jsonl
# sensitivity
0| sensitivity $P $Q --metric losses_W.total --delta thermal_expansion
2| sensitivity $P $Q --metric no.such_metric --delta thermal_expansion
3| sensitivity $CL --max-wall 0.001 --metric losses_W.total
4| STDOUT_FULL sensitivity $P $Q --metric losses_W.total --delta thermal_expansion
# study
0| study $P $Q
2| study $P --csv $NX/s.csv
2| study $TMP/seed.ini --csv $TMP/seed.ini
2| study $P --csv $P
2| study $P --csv $LONG
2| study $P --max-wall -3
3| study $CL --max-wall 0.001 --csv -
4| study $P $Q --csv /dev/full
4| STDOUT_FULL study $P $Q
# plot
0| plot $P $Q --out $TMP/p.png
2| plot $TMP/keep.ini $Q --out $TMP/keep.ini
2| plot $P $Q --kind nosuch
3| plot $P $Q --set thermal.max_steps=2
4| NOGNUPLOT plot $P $Q --out $TMP/p2.png
4| STDOUT_FULL plot $P $Q
# bench speed
0| bench speed $P $Q --repeat 1
2| bench speed $P --repeat 0
3| bench speed $P $Q --set thermal.max_steps=2 --repeat 1
4| STDOUT_FULL bench speed $P $Q --repeat 1
# bench accuracy
0| bench accuracy $P $Q --repeat 1 --knobs contact_grid
2| bench accuracy $P $Q --repeat 1 --knobs contact_grid --csv $NX/a.csv
3| bench accuracy $P $Q --set thermal.max_steps=2 --repeat 1 --knobs contact_grid
4| STDOUT_FULL bench accuracy $P $Q --repeat 1 --knobs contact_grid
# report
0| report $P $Q
2| report $P $Q --md $NX/r.md
3| report $CL --max-wall 0.001 --json
4| STDOUT_FULL report $P $Q
# new
0| new 7014C --out $TMP/n0.ini
2| new 7014C --out $TMP/n0.ini
2| new XYZ
2| new 7014C --out $NX/n.ini
4| FSIZE new 7014C --out $TMP/n.ini
4| STDOUT_FULL new 7014C --out $TMP/n4.ini
# preload-map
0| preload-map $P $Q --speeds 4000:8000:2 --preloads 100:200:2
2| preload-map $P --speeds 150000:200000:2 --preloads 100:200:2
2| preload-map $P $Q --speeds 4000:8000:2 --preloads 100:200:2 --csv $NX/m.csv
3| preload-map $P --speeds 4000:8000:2 --preloads 100:200:2 --set thermal.max_steps=2
4| preload-map $P $Q --speeds 4000:8000:2 --preloads 100:200:2 --csv /dev/full
4| STDOUT_FULL preload-map $P $Q --speeds 4000:8000:2 --preloads 100:200:2
# the listings
0| presets
2| presets $NX
4| STDOUT_FULL presets
0| keys
2| keys extra
4| STDOUT_FULL keys
0| metrics --json
2| metrics --bogus
4| STDOUT_FULL metrics
0| schema
2| schema extra
4| STDOUT_FULL schema
0| help run
2| help nosuch
4| STDOUT_FULL help
0| version
2| version extra
4| STDOUT_FULL version
EOF_TABLE

# The README's table, command by command: every entry that is not "—" has
# a case above that gave it (an entry "not reached by any shipped preset"
# is said as a skip).
awk -F'|' '/^\| Command \| 0 \| 2 \| 3 \| 4 \|$/ { on = 1; next } /^$/ { on = 0 }
    on && /^\| `[a-z]/ { gsub(/`/, "", $2); gsub(/^ +| +$/, "", $2);
        split("0 2 3 4", c, " ");
        for (k = 1; k <= 4; k++) { v = $(k + 2); gsub(/^ +| +$/, "", v);
            if (v != "—") print $2 "|" c[k] "|" (v ~ /not reached/ ? "skip" : "need") } }' \
    README.md >"$TMP/claims"
[ "$(wc -l <"$TMP/claims")" -ge 60 ]
t $? "the README's exit-code table read ($(wc -l <"$TMP/claims") entries)"
while IFS='|' read -r cmd c kind; do
    if [ "$kind" = skip ]; then
        skip "README: $cmd exits $c" "not reached by any shipped preset"
    else
        grep -qxF "$cmd|$c" "$TMP/covered"
        t $? "README: $cmd exits $c (a case above gave it)"
    fi
done <"$TMP/claims"

[ "$(cmp -s "$TMP/keep.ini" "$P"; echo $?)" = 1 ] && grep -q '^axial_load_N = 1000$' "$TMP/keep.ini" &&
    ! grep -q '^iteration,' "$TMP/keep.ini"
t $? "the preset named as --csv is still the preset (only the edit changed it)"

cmp -s "$TMP/seed.ini" "$P" && cmp -s "$P" presets/7008C.ini && [ ! -e "$TMP/dl-target.csv" ]
t $? "study --csv PRESET left the preset alone; the dangling link's target was not made"

# issue 26 item 9: edit saved what check and run then refused. VG2 is a
# listed grade, valid from viscosity_index ~160 (its nu100 reaches the
# 1 mm^2/s the viscosity law takes); the refusal names the grade and index.
"$ACBB" edit "$TMP/seed.ini" --set lubricant.grade=VG2 >/dev/null 2>"$TMP/err"
has "$TMP/err" "lubricant.grade = VG2 with lubricant.viscosity_index = 100 derives" \
    "edit VG2: the message names the grade and the index"
cp "$P" "$TMP/vg2.ini"
"$ACBB" edit "$TMP/vg2.ini" --set lubricant.grade=VG2 --set lubricant.viscosity_index=200 \
    >/dev/null 2>&1 && "$ACBB" check "$TMP/vg2.ini" >/dev/null 2>&1 &&
    "$ACBB" run "$TMP/vg2.ini" $Q --quiet >/dev/null 2>&1
t $? "VG2 at viscosity_index 200: edit saves it, check and run accept it"

# The full-disk cases above left no trace.
cmp -s "$TMP/seed.ini" "$P" && [ ! -e "$TMP/n.ini" ]
t $? "edit and new on a full disk: the preset unchanged, no new file left"

# --json: exactly one document on stdout whatever the exit (issue 26 item
# 8); on exit 2 its message is the error, never a "note:" line. The third
# case printed run's failure record and then a bad_input document; the
# fourth had the note as its message.
N="--set effects.thermal_expansion=off --set effects.ring_centrifugal=on"
while IFS='|' read -r want args; do
    # shellcheck disable=SC2086
    "$ACBB" $args --json >"$TMP/out" 2>"$TMP/err" </dev/null
    code $? "$want" "acbb$args --json"
    jq -e -s 'length == 1 and (.[0].message | (startswith("note:") or startswith("warning:")) | not)
        and (.[0].status != "converged")' "$TMP/out" >/dev/null 2>&1
    t $? "... one document on stdout, its message the error: $(head -c 120 "$TMP/out" | tr -s "\n " " ")"
done <<EOF_JSON
2| run $P --josn
2| run $P --set bearing.n_balls=0
2| run $P --set lubricant.grade=VG2
2| run $P $N --set lubricant.grade=VG2
2| run $P $N --set bearing.cage_width_mm=1e-06
2| run $TMP/keep.ini $Q --csv $TMP/keep.ini
2| sweep $P $Q --param operating.axial_load_N --values 100,-1
2| report $P $N --set bearing.n_balls=0
2| metrics --bogus
3| run $P $Q --set thermal.max_steps=2
EOF_JSON

# --max-wall: the named status and the last good state in the JSON. The
# scene: a quasi-static set-up (milliseconds) and a [schedule] of 9e7 s
# (3 million steps of at most 30 s, minutes on any machine), bounded at
# 0.5 s: the bound ends it, whatever the machine, after some steps.
cp "$P" "$TMP/long.ini"
sed -i 's/^max_time_s = .*/max_time_s = 1e8/; s/^max_steps = .*/max_steps = 10000000/' "$TMP/long.ini"
printf '\n[schedule]\nrow = 0, 15000, 300, 0\nrow = 90000000, 15000, 300, 0\n' >>"$TMP/long.ini"
"$ACBB" run "$TMP/long.ini" $Q --max-wall 0.5 --json >"$TMP/w.json" 2>"$TMP/err"
code $? 3 "--max-wall 0.5 on a 9e7 s schedule"
jq -e '.status == "wall_limit" and .iterations >= 1 and (.losses_W.total | . > 0)
    and .time_s < 9e7 and (.message | test("fidelity.max_wall_s = 0.5 s reached; last good state kept"))' \
    "$TMP/w.json" >/dev/null 2>&1
t $? "--max-wall ends wall_limit with the last good state (losses, iterations)"
# The bound covers the set-up too (issue 20 item 8): the dynamic level's
# set-up of combined-load (every ball's first window, 21 balls) takes far
# longer than 1 ms on any machine; before, the set-up and a first step ran
# whole (iterations 1) whatever the bound.
"$ACBB" run presets/combined-load.ini --set fidelity.model=dynamic --max-wall 0.001 --json \
    >"$TMP/w3.json" 2>"$TMP/err"
code $? 3 "--max-wall 0.001 during a dynamic set-up"
jq -e '.status == "wall_limit" and .iterations == 0
    and (.message | test("reached during the set-up"))
    and ([.. | numbers | select(isinfinite or isnan)] | length == 0)' "$TMP/w3.json" >/dev/null 2>&1
t $? "... ends wall_limit in the set-up: no step taken, finite JSON, the message says so"
grep -q -x -F "acbb: wall_limit: $(jq -r .message "$TMP/w3.json")" "$TMP/err"
t $? "... and stderr names it as a step's bound: 'wall_limit: ' then the JSON's message (test wall_message)"
# A sweep's points are bounded alike: each record says wall_limit, exit 3.
"$ACBB" sweep presets/combined-load.ini --set fidelity.model=dynamic \
    --grid operating.axial_load_N=300,400 --max-wall 0.001 --jsonl "$TMP/w5.jsonl" >/dev/null 2>"$TMP/err"
code $? 3 "sweep --max-wall 0.001 at the dynamic level"
[ "$(tail -n +2 "$TMP/w5.jsonl" | jq -r .status | sort -u)" = wall_limit ]
t $? "... every point's record says wall_limit"
# A bearing set too (its run loop checks the bound between the set's
# steps; before, a set was never bounded): a DB pair on the 9e7 s schedule.
cp presets/pair-DB-heated.ini "$TMP/pair.ini"
printf '\n[thermal]\nmax_time_s = 1e8\nmax_steps = 10000000\n\n[schedule]\nrow = 0, 15000, 300, 0\nrow = 90000000, 15000, 300, 0\n' \
    >>"$TMP/pair.ini"
timeout 120 "$ACBB" run "$TMP/pair.ini" $Q --max-wall 0.5 --json >"$TMP/w4.json" 2>"$TMP/err"
code $? 3 "--max-wall 0.5 on a bearing set"
jq -e '.status == "wall_limit" and .iterations >= 1 and .time_s < 9e7
    and ([.. | numbers | select(isinfinite or isnan)] | length == 0)' "$TMP/w4.json" >/dev/null 2>&1
t $? "... ends wall_limit after some steps, the set's JSON says so, finite"
# Its other branch (displacement preload: the steady solve runs too) gets
# what the run left of the one bound, here nothing (issue 26 item 7; before,
# a second 0.5 s, in which the quasi-static pair's steady solve converged).
jq -e '.branches.steady.status == "wall_limit" and .branches.steady.iterations == 0
    and (.branches.steady.message | test("0.5 s \\(the run and the other branch together\\)"))' \
    "$TMP/w4.json" >/dev/null 2>&1
t $? "... and its other branch is not started: one bound for the whole command"
"$ACBB" run "$P" $Q --set fidelity.max_wall_s=1000 --json >"$TMP/w2.json" 2>/dev/null
jq -e --slurpfile b "$TMP/base.json" '.status == "converged" and .losses_W.total == $b[0].losses_W.total
    and .iterations == $b[0].iterations' "$TMP/w2.json" >/dev/null 2>&1
t $? "a bound not reached changes nothing (same losses, same steps)"

# No inf / nan in text: a baseline whose change overflows.
jq '.losses_W.total = 1e-320 | .temperature_C.outer_ring = 1e308' "$TMP/base.json" >"$TMP/odd.json"
"$ACBB" run "$P" $Q --set operating.axial_load_N=900 --baseline "$TMP/odd.json" >"$TMP/out" 2>&1
! grep -qiw -e inf -e nan -e '-inf%' -e 'inf%' "$TMP/out" && grep -q 'losses_W.total' "$TMP/out"
t $? "--baseline: an overflowing change prints '-', never inf or nan"
"$ACBB" run "$P" $Q --set operating.axial_load_N=900 --baseline "$TMP/odd.json" --json >"$TMP/out" 2>&1
jq -e '[.vs_baseline[] | select(.path == "losses_W.total")][0].change_pct == null' "$TMP/out" >/dev/null 2>&1
t $? "--baseline --json: the overflowing percentage is null"
"$ACBB" run "$P" $Q --baseline "$TMP/base.json" --quiet >"$TMP/out" 2>&1
[ ! -s "$TMP/out" ]
t $? "--quiet with --baseline prints nothing"

# FIFOs: no reader is said at once; a FIFO preset is named as one.
if mkfifo "$TMP/fifo" 2>/dev/null; then
    timeout 60 "$ACBB" sweep "$P" $Q $G --jsonl "$TMP/fifo" >/dev/null 2>"$TMP/err"
    code $? 2 "sweep --jsonl FIFO without a reader exits 2 at once"
    has "$TMP/err" "a FIFO with no reader" "... saying so"
    timeout 60 "$ACBB" run "$P" $Q --csv "$TMP/fifo" >/dev/null 2>"$TMP/err"
    code $? 2 "run --csv FIFO without a reader exits 2 at once"
    # study used to run its 48 points first and fail at the end (issue 26).
    timeout 60 "$ACBB" study "$P" --csv "$TMP/fifo" >"$TMP/out" 2>"$TMP/err"
    code $? 2 "study --csv FIFO without a reader exits 2"
    [ ! -s "$TMP/out" ]
    t $? "... before anything runs (no table)"
    # The reader is there before the sweep starts (a background `cat` may
    # open it too late): the shell holds the FIFO open read-write on fd 3.
    exec 3<>"$TMP/fifo"
    timeout 60 "$ACBB" sweep "$P" $Q $G --jsonl "$TMP/fifo" >/dev/null 2>&1
    code $? 0 "sweep --jsonl FIFO with a reader streams into it"
    timeout 10 head -n 3 <&3 >"$TMP/fifo.out"
    exec 3<&-
    [ "$(wc -l <"$TMP/fifo.out")" -eq 3 ]
    t $? "... the header and both records"
    (cd "$TMP" && timeout 60 "$ACBB" run fifo) >/dev/null 2>"$TMP/err"
    code $? 2 "a FIFO preset is refused"
    has "$TMP/err" "a FIFO, not a regular file" "... as a FIFO, not 'no such file'"
    # --baseline FIFO (issue 26 item 7): before, the read waited for a
    # writer for ever; now it is refused before the run (the guard below
    # is a hang guard, 124, not a timing check).
    timeout 60 "$ACBB" run "$P" $Q --baseline "$TMP/fifo" >/dev/null 2>"$TMP/err"
    code $? 2 "run --baseline FIFO exits 2 at once"
    has "$TMP/err" "--baseline $TMP/fifo: not a regular file" "... saying it is not a regular file"
fi
timeout 60 "$ACBB" run "$P" $Q --baseline "$TMP" --json >"$TMP/out" 2>"$TMP/err"
code $? 2 "run --baseline DIRECTORY exits 2"
jq -e '.status == "bad_input" and (.message | test("not a regular file")) and (has("losses_W") | not)' \
    "$TMP/out" >/dev/null 2>&1 && grep -q "not a regular file" "$TMP/err"
t $? "... before the run: the bad_input record (no run document), the reason on stderr"
tap_done
