#!/bin/sh
# acbb sweep in N shards through GNU parallel, on this machine or on many
# over ssh, then merged into OUTDIR/sweep.jsonl (the canonical table, equal
# byte for byte to one machine's `acbb merge OUT sweep.jsonl`).
#
#   acbb-sweep-parallel.sh N OUTDIR PRESET [acbb sweep options]
#
# Environment:
#   SSHLOGIN   GNU parallel's --sshlogin, e.g. "1/node1,1/node2" (one shard
#              at a time per host; acbb uses every core of it). acbb and the
#              preset must exist on every host; OUTDIR is created under the
#              same path there and each shard file is copied back (--return).
#   ACBB       the acbb binary (default: acbb)
#   ACBB_JOBS  threads per shard (default: every CPU; set 1 when N shards
#              share one machine)
# A shard that fails can be re-run with the same command: it resumes.
# Exit: 0 when every shard ran (points that did not converge, acbb's exit
# 3, are results recorded in the files); 1 when a shard failed (the shards
# there are still merged); 3 when every shard ran but points are missing
# (merge's 3: --max-points); the merge's status when the merge fails.
set -u
n=${1:?usage: acbb-sweep-parallel.sh N OUTDIR PRESET [sweep options]}
out=${2:?usage: acbb-sweep-parallel.sh N OUTDIR PRESET [sweep options]}
shift 2
ACBB=${ACBB:-acbb}
mkdir -p "$out"
jobs=${ACBB_JOBS:+--jobs $ACBB_JOBS}
if [ -n "${SSHLOGIN:-}" ]; then
    # shellcheck disable=SC2086
    parallel --will-cite -q --sshlogin "$SSHLOGIN" --workdir . --return "$out/shard-{}.jsonl" \
        sh -c 'mkdir -p "$1" && shift && { "$@"; r=$?; [ "$r" -eq 3 ] && r=0; exit "$r"; }' sh "$out" \
        "$ACBB" sweep "$@" --shard "{}/$n" $jobs --jsonl "$out/shard-{}.jsonl" ::: $(seq "$n")
else
    # shellcheck disable=SC2086
    parallel --will-cite -q -j "$n" sh -c '"$@"; r=$?; [ "$r" -eq 3 ] && r=0; exit "$r"' sh \
        "$ACBB" sweep "$@" --shard "{}/$n" $jobs --jsonl "$out/shard-{}.jsonl" ::: $(seq "$n")
fi
rc=$?
# parallel's exit status counts the failed shards (exit 3 is mapped to 0
# above: non-converged points are in the files). Merge whatever is there.
# merge exits 3 when points are missing (it still writes the others).
"$ACBB" merge "$out/sweep.jsonl" "$out"/shard-*.jsonl
m=$?
[ "$m" -ne 0 ] && [ "$m" -ne 3 ] && exit "$m"
if [ "$rc" -ne 0 ]; then
    echo "acbb-sweep-parallel: $rc shard(s) failed; re-run the same command to resume them" >&2
    exit 1
fi
exit "$m"
