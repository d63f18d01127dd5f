#!/usr/bin/env bash
# Every long command cancels the same way (issue 16, item 2): for each of
# run, sweep (--grid and --param/--values), study (PRESET and seed --out),
# report (with and without --sensitivity), sensitivity, bench speed and
# bench accuracy, SIGINT and, separately, SIGTERM mid-run end it with exit
# 3, status `cancelled` (stderr, and the JSON where it prints JSON), the
# finished part written and no file that looks complete when it is not.
# No clock is asserted: each command is started, a STATE is awaited (its
# handler installed, its progress line, its first record; bounded polls),
# then signalled; the inputs run for minutes uncancelled (dynamic level,
# thousands of points). $1 = the acbb binary; $2 = `quick` (the default
# suite): SIGTERM only for run and sweep --grid, since one handler serves
# both signals (cli/progress.c); without it (the slow suite) every command
# under both.
. "$(dirname "$0")/tap.sh"
ACBB=$1
MODE=${2:-all}
P=$PWD/presets
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
export ACBB_PROGRESS=1     # the progress lines are the states awaited

# caught PID: the process runs acbb and catches SIGINT and SIGTERM (its
# handler is in). The exe check matters (issue 28 item 14): between fork
# and exec the background job is this script's own bash, which also
# catches both; a SIGINT sent then ran this script's EXIT trap in that
# child (rm -rf $TMP) and ended it by SIGINT (exit 130), and every later
# check failed on missing files.
ACBB_EXE=$(readlink -f "$ACBB")
caught() {
    local m
    [ "$(readlink "/proc/$1/exe" 2>/dev/null)" = "$ACBB_EXE" ] || return 1
    m=$(awk '/^SigCgt:/ { print $2 }' "/proc/$1/status" 2>/dev/null)
    [ -n "$m" ] && (( (16#$m & 0x4002) == 0x4002 ))
}

# reached PID STATE: STATE is `caught`, `file:PATH` (PATH not empty) or a
# pattern the (\r-split) stderr shows on a line of its own.
reached() {
    case "$2" in
        caught) caught "$1" ;;
        file:*) [ -s "${2#file:}" ] ;;
        # a finished point's record (a sweep file starts with its header)
        record:*) grep -q '"index"' "${2#record:}" 2>/dev/null ;;
        *) tr '\r' '\n' <"$TMP/err" 2>/dev/null | grep -q -- "$2" ;;
    esac
}

# cancel SIG STATE CMD...: start `acbb CMD...` (stdout $TMP/out, stderr
# $TMP/err), wait (bounded, 120 s) for STATE, send SIG; rc = its exit status.
cancel() {
    local sig=$1 state=$2 i pid
    shift 2
    # Emptied here, not by the child's redirection: until the child runs,
    # the previous command's stderr would match STATE, and a SIGINT sent
    # before the handler is in is lost (a script's background job ignores it).
    : >"$TMP/out"
    : >"$TMP/err"
    "$ACBB" "$@" >"$TMP/out" 2>"$TMP/err" &
    pid=$!
    for ((i = 0; i < 1200; i++)); do
        reached $pid "$state" && break
        kill -0 $pid 2>/dev/null || break
        sleep 0.1
    done
    kill -"$sig" $pid 2>/dev/null
    wait $pid
    rc=$?
}

# said NAME CMD SIG: stderr reports the cancel by that signal.
said() {
    tr '\r' '\n' <"$TMP/err" | grep -q "^acbb: $2: cancelled by $3"
    t $? "$1: stderr says '$2: cancelled by $3'"
}

GRID=(--grid operating.axial_load_N=50:1000:1000 --grid operating.ambient_C=20:30:1000)
for sig in INT TERM; do
    S=SIG$sig

    # run: cancelled once its handler is in (the dynamic level's set-up or
    # first steps); the JSON says so. tests/unending.ini cannot converge
    # first on any machine (combined-load itself ends in about a second).
    cancel $sig caught run "$(dirname "$0")/unending.ini" --json
    code $rc 3 "run, $S"
    jqt "$TMP/out" '.status == "cancelled"' "run, $S: JSON status cancelled"
    has "$TMP/err" "cancelled" "run, $S: stderr says cancelled"

    # sweep --grid: the finished points stay in both files; a re-run resumes.
    # (1000 x 1000 points: minutes on any machine, so the sweep is still
    # running when the signal follows its first record; 4000 points took a
    # few seconds in all)
    rm -f "$TMP/s.jsonl" "$TMP/s.csv"
    cancel $sig "record:$TMP/s.jsonl" sweep "$P/7008C.ini" "${GRID[@]}" \
        --jsonl "$TMP/s.jsonl" --csv "$TMP/s.csv"
    code $rc 3 "sweep --grid, $S"
    said "sweep --grid, $S" sweep $S
    # (after the sweep header line; the CSV has the column header, its
    # header line is in s.csv.json)
    k=$(jq -s 'map(select(has("index"))) | length' "$TMP/s.jsonl")
    [ "${k:-0}" -ge 1 ] && [ "$(jq -s 'map(select(has("index"))) | [.[].index] | unique | length' "$TMP/s.jsonl")" = "$k" ] &&
        [ "$(($(wc -l <"$TMP/s.csv") - 1))" -eq "$k" ]
    t $? "sweep --grid, $S: $k finished points, each once, in the JSONL and the CSV"
    jqt "$TMP/s.jsonl" '.status == "converged"' "sweep --grid, $S: every record is a finished point"
    "$ACBB" sweep "$P/7008C.ini" "${GRID[@]}" \
        --jsonl "$TMP/s.jsonl" --csv "$TMP/s.csv" --max-points 2 >/dev/null 2>"$TMP/err"
    code $? 0 "sweep --grid, $S: the same command again"
    grep -q "resuming, $k points\? already there" "$TMP/err" &&
        [ "$(jq -s 'map(select(has("index"))) | [.[].index] | unique | length' "$TMP/s.jsonl")" = $((k + 2)) ]
    t $? "sweep --grid, $S: the re-run resumed ($k kept, 2 more)"

    # One handler serves both signals: the quick pass stops TERM here.
    [ "$sig" = TERM ] && [ "$MODE" = quick ] && continue

    # sweep --param/--values: the table keeps the finished points, the rest
    # are marked cancelled (JSON on stdout; the CSV likewise).
    # (2000 dynamic-level points: minutes on any machine)
    cancel $sig 'sweep: [1-9]' sweep "$P/7008C.ini" --param operating.axial_load_N \
        --values "$(seq -s, 50 1 2049)" --set fidelity.model=dynamic --json --csv "$TMP/p.csv"
    code $rc 3 "sweep --param, $S"
    said "sweep --param, $S" sweep $S
    jqt "$TMP/out" 'length == 2000 and (map(select(.status == "converged")) | length >= 1)
        and (map(select(.status == "cancelled")) | length >= 1)
        and all(.[]; .status == "converged" or .status == "cancelled")' \
        "sweep --param, $S: JSON has the finished points, the others cancelled"
    [ "$(grep -c ',converged,' "$TMP/p.csv")" -ge 1 ] && grep -q ',cancelled,' "$TMP/p.csv"
    t $? "sweep --param, $S: the CSV marks the unfinished points cancelled"

    # study PRESET: the table shows which runs finished; a run the cancel
    # stopped mid-way shows no numbers (they would be an unfinished
    # transient's), in the table as in the CSV.
    # (tests/unending.ini: its runs cannot end, so the study is still going
    # when the signal comes; 7008C's dynamic level took a few seconds of
    # CPU in all, spread over every core)
    cancel $sig caught study "$(dirname "$0")/unending.ini" --csv "$TMP/s.csv"
    code $rc 3 "study PRESET, $S"
    said "study PRESET, $S" study $S
    grep -q 'cancelled' "$TMP/out"
    t $? "study PRESET, $S: the table marks the cancelled runs"
    # Per row, the table's "-" cells are the CSV's cancelled sides: three
    # each (T, P, Qi), and dP's two when either side is.
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
             { te = $c["te_status"] == "cancelled"; wte = $c["wte_status"] == "cancelled"
               print 3 * te + 3 * wte + 2 * (te || wte) }' "$TMP/s.csv" >"$TMP/s.want"
    awk '/^[*]? *[0-9]+  / { sub(/^[*]/, ""); d = 0; for (i = 2; i <= 9; i++) d += $i == "-"; print d }' \
        "$TMP/out" >"$TMP/s.got"
    [ -s "$TMP/s.want" ] && cmp -s "$TMP/s.want" "$TMP/s.got"
    t $? "study PRESET, $S: a cancelled run shows no numbers in the table"
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
             { for (m = 0; m < 2; m++) {
                   s = m ? c["wte_status"] : c["te_status"]
                   e = m ? c["dP_total_W"] : c["wte_status"]
                   if ($s != "cancelled") continue
                   n++
                   for (i = s + 2; i < e; i++) if ($i != "") bad = 1 } }
             END { exit bad || !n }' "$TMP/s.csv"
    t $? "study PRESET, $S: the CSV's cancelled runs have empty values"

    # study seed --out DIR: no REPORT.md claiming a complete set.
    rm -rf "$TMP/figs"
    cancel $sig 'study: running' study seed --out "$TMP/figs" --set fidelity.model=dynamic
    code $rc 3 "study seed --out, $S"
    said "study seed --out, $S" study $S
    [ ! -e "$TMP/figs/REPORT.md" ]
    t $? "study seed --out, $S: no REPORT.md"

    # report --md F --json: no verdicts, no F, JSON status.
    rm -f "$TMP/r.md"
    cancel $sig 'report: running' report "$P/7008C.ini" --set fidelity.model=dynamic \
        --md "$TMP/r.md" --json
    code $rc 3 "report, $S"
    said "report, $S" report $S
    jqt "$TMP/out" '.status == "cancelled" and .signal == "'$S'"' \
        "report, $S: JSON status cancelled"
    python3 "$(dirname "$0")/schema_check.py" docs/schema/acbb.schema.json --def cancelled "$TMP/out"
    t $? "report, $S: the cancelled document conforms to the schema (schema_version 4)"
    [ ! -e "$TMP/r.md" ]
    t $? "report, $S: no --md file"

    # report --sensitivity --md F, cancelled in the robustness runs (the
    # issue's case: it exited 0 and wrote F without the section).
    cancel $sig 'robustness: [1-9]' report "$P/7008C.ini" --sensitivity --md "$TMP/r.md"
    code $rc 3 "report --sensitivity, $S"
    said "report --sensitivity, $S" report $S
    [ ! -e "$TMP/r.md" ] && [ ! -s "$TMP/out" ]
    t $? "report --sensitivity, $S: no --md file, no verdicts printed"

    # sensitivity: no partial table or CSV; JSON status.
    rm -f "$TMP/sens.csv"
    cancel $sig 'sensitivity: [1-9]' sensitivity "$P/7008C.ini" --metric losses_W.total \
        --morris 1000 --json --csv "$TMP/sens.csv"
    code $rc 3 "sensitivity, $S"
    said "sensitivity, $S" sensitivity $S
    jqt "$TMP/out" '.status == "cancelled" and .schema_version == 4' \
        "sensitivity, $S: JSON status cancelled, schema_version 4"
    [ ! -e "$TMP/sens.csv" ]
    t $? "sensitivity, $S: no --csv file"

    # bench speed: cancelled among its 100000 repeats.
    cancel $sig caught bench speed "$P/7008C.ini" --repeat 100000
    code $rc 3 "bench speed, $S"
    said "bench speed, $S" "bench speed" $S

    # bench accuracy: the settings timed so far, no --csv file.
    rm -f "$TMP/acc.csv"
    cancel $sig 'accuracy: [1-9]' bench accuracy "$P/7008C.ini" --csv "$TMP/acc.csv"
    code $rc 3 "bench accuracy, $S"
    said "bench accuracy, $S" "bench accuracy" $S
    grep -q '^setting ' "$TMP/out" && [ ! -e "$TMP/acc.csv" ]
    t $? "bench accuracy, $S: the finished settings printed, no --csv file"
done

tap_done
