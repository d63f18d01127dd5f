#!/bin/bash
# Sweeps beyond one machine, end to end (TAP; meson suite `slurm`, run by
# .ci/run, not by a plain `meson test`). Starts a single-node Slurm in a
# temporary directory (munged, slurmctld, slurmd as root, 2 CPUs), submits
# contrib/slurm/acbb-sweep.sbatch for a two-shard sweep plus its dependent
# merge job, and compares the merge byte for byte with the one-machine
# sweep. When Slurm cannot start here (not root, packages missing, a
# container that refuses slurmd) the Slurm checks are skipped with the
# reason and the GNU parallel recipe (contrib/parallel, local) is checked
# the same way. $1 = the acbb binary; cwd = repository root.
set -u

ACBB=$(cd "$(dirname "${1:?usage: test_slurm.sh path/to/acbb}")" && pwd)/$(basename "$1")
PRESET=$PWD/presets/7008C.ini
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-slurm.XXXXXX") || exit 1
chmod 755 "$TMP"
PIDS=""
cleanup() {
    for p in $PIDS; do kill "$p" 2>/dev/null; done
    sleep 0.5
    for p in $PIDS; do kill -9 "$p" 2>/dev/null; done
    rm -rf "$TMP"
}
trap cleanup EXIT INT TERM
export XDG_CONFIG_HOME="$TMP/xdg"

. "$(dirname "$0")/tap.sh"

GRID=(--set fidelity.model=quasi-static --grid operating.axial_load_N=200,800
      --grid operating.inner_speed_rpm=4000,8000,12000)

"$ACBB" sweep "$PRESET" "${GRID[@]}" --jsonl "$TMP/one.jsonl" 2>"$TMP/err"
code $? 0 "one-machine sweep (6 points)"
"$ACBB" merge "$TMP/canon.jsonl" "$TMP/one.jsonl" 2>"$TMP/err"
[ "$(wc -l <"$TMP/canon.jsonl")" -eq 7 ] # the header + 6
t $? "its canonical form has 6 records"

# ---- a single-node Slurm ----
why=""
start_munge() {
    dd if=/dev/urandom of="$TMP/munge.key" bs=1024 count=1 2>/dev/null
    chmod 400 "$TMP/munge.key"
    mkdir -p "$TMP/munge"
    munged --force --key-file="$TMP/munge.key" --socket="$TMP/munge/sock" \
        --pid-file="$TMP/munge/pid" --log-file="$TMP/munge/log" --seed-file="$TMP/munge/seed" \
        >/dev/null 2>&1 || return 1
    PIDS="$PIDS $(cat "$TMP/munge/pid" 2>/dev/null)"
    AUTH="AuthType=auth/munge
AuthInfo=socket=$TMP/munge/sock"
}

write_conf() {
    local port=$((20000 + $$ % 20000)) host
    host=$(hostname -s)
    mkdir -p "$TMP/state" "$TMP/spool"
    cat >"$TMP/slurm.conf" <<EOF
ClusterName=acbbtest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
$AUTH
StateSaveLocation=$TMP/state
SlurmdSpoolDir=$TMP/spool
SlurmctldPidFile=$TMP/slurmctld.pid
SlurmdPidFile=$TMP/slurmd.pid
SlurmctldLogFile=$TMP/slurmctld.log
SlurmdLogFile=$TMP/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
    export SLURM_CONF="$TMP/slurm.conf"
}

# The node is up when sinfo says idle (bounded wait).
wait_idle() {
    for _ in $(seq 60); do
        sinfo -h -o %t 2>/dev/null | grep -q '^idle' && return 0
        sleep 0.5
    done
    return 1
}

start_slurm() {
    [ "$(id -u)" -eq 0 ] || { why="not root"; return 1; }
    for p in munged slurmctld slurmd sbatch sinfo; do
        command -v $p >/dev/null || { why="$p not installed (slurm-wlm, munge)"; return 1; }
    done
    AUTH="AuthType=auth/none
CredType=cred/none"
    start_munge || echo "# munged did not start; Slurm with auth/none"
    write_conf
    slurmctld -D -f "$SLURM_CONF" >"$TMP/slurmctld.out" 2>&1 &
    PIDS="$PIDS $!"
    slurmd -D -f "$SLURM_CONF" >"$TMP/slurmd.out" 2>&1 &
    PIDS="$PIDS $!"
    if ! wait_idle; then
        why="slurmd/slurmctld did not come up: $(tail -n 3 "$TMP"/slurmd.out "$TMP"/slurmd.log \
            "$TMP"/slurmctld.log 2>/dev/null | grep -v '^==' | grep . | tail -n 1 | tr -d '\r')"
        return 1
    fi
}

# Poll until every task of both jobs has ended (bounded: 120 s). The
# states are read with --states=all, and only from a squeue that answered:
# an empty answer used to mean "finished", and a squeue that failed (a
# slurmctld slow to answer on a loaded machine) printed nothing too, so the
# shards were read before the jobs had written them.
wait_jobs() {
    local st
    for _ in $(seq 240); do
        if st=$(squeue -h --states=all -j "$1,$2" -o %T 2>/dev/null) && [ -n "$st" ] &&
            ! grep -qvE '^(COMPLETED|FAILED|CANCELLED|TIMEOUT|OUT_OF_MEMORY|NODE_FAIL|PREEMPTED|BOOT_FAIL|DEADLINE)$' <<<"$st"; then
            return 0
        fi
        sleep 0.5
    done
    return 1
}

if start_slurm; then
    t 0 "single-node Slurm is up (2 CPUs)"
    jid=$(cd "$TMP" && ACBB="$ACBB" sbatch --parsable --array=1-2 -o "$TMP/task-%a.out" \
        "$OLDPWD/contrib/slurm/acbb-sweep.sbatch" "$TMP/out" "$PRESET" "${GRID[@]}" 2>"$TMP/err")
    t $? "sbatch of the job array (2 shards)"
    mid=$(cd "$TMP" && ACBB="$ACBB" sbatch --parsable --dependency="afterok:$jid" \
        -o "$TMP/merge.out" "$OLDPWD/contrib/slurm/acbb-sweep.sbatch" --merge "$TMP/out" 2>"$TMP/err")
    t $? "sbatch of the dependent merge job"
    wait_jobs "$jid" "$mid"
    t $? "both jobs finished within 120 s"
    [ -s "$TMP/out/shard-1.jsonl" ] && [ -s "$TMP/out/shard-2.jsonl" ]
    t $? "each array task wrote its shard"
    cmp -s "$TMP/out/sweep.jsonl" "$TMP/canon.jsonl"
    t $? "Slurm: merged shards == one-machine canonical output, byte for byte"
else
    for name in "single-node Slurm is up" "sbatch of the job array" "sbatch of the merge job" \
                "jobs finished" "shards written" "Slurm merge == one-machine output"; do
        skip "$name" "$why"
    done
fi

# ---- GNU parallel (local, no ssh) ----
if command -v parallel >/dev/null; then
    ACBB="$ACBB" ACBB_JOBS=1 contrib/parallel/acbb-sweep-parallel.sh 2 "$TMP/par" "$PRESET" \
        "${GRID[@]}" >"$TMP/par.out" 2>"$TMP/err"
    code $? 0 "GNU parallel recipe, 2 shards"
    [ "$(wc -l <"$TMP/par/shard-1.jsonl")" -eq 4 ] && [ "$(wc -l <"$TMP/par/shard-2.jsonl")" -eq 4 ]
    t $? "each shard holds 3 of the 6 points"
    cmp -s "$TMP/par/sweep.jsonl" "$TMP/canon.jsonl"
    t $? "parallel: merged shards == one-machine canonical output, byte for byte"
else
    skip "GNU parallel recipe" "parallel not installed"
fi

tap_done
