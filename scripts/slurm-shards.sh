#!/usr/bin/env bash
# A rotbeam suite or study over a Slurm job array (docs/distributed-runs.md): N array tasks, task
# I running `rotbeam ... --shard I/N --out OUT/shard-I` on the CPUs Slurm gives it, and one merge
# job that starts when every task has ended (afterany: also when one failed, so that the merge
# lists what is missing) and writes OUT/merged.
#
# usage: scripts/slurm-shards.sh N OUT [sbatch options...] -- ROTBEAM_ARGUMENTS...
#   e.g. scripts/slurm-shards.sh 16 /scratch/rb --partition=short --time=01:00:00 -- suite
#        scripts/slurm-shards.sh 4 /scratch/rb -- study all --quick
# Environment: ROTBEAM (the program, default: rotbeam on PATH), CPUS (per task, default 2),
# TIMINGS (an earlier output folder whose run times balance the shards; optional),
# SBATCH (default sbatch; SBATCH=echo prints the two submissions instead).
#
# OUT must be on a file system every node sees. A task that dies (node failure, time limit) leaves
# its finished runs in OUT/shard-I; the merge job then exits 5 and lists the runs and the command
# that makes them; resubmit that task alone (sbatch --array=I ... as printed below) — it resumes —
# and run the merge again.
set -eu
if [ $# -lt 4 ]; then
    sed -n '8,11p' "$0" >&2
    exit 2
fi
n=$1 out=$2
shift 2
options=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    options+=("$1")
    shift
done
[ "${1:-}" = "--" ] || { echo "slurm-shards.sh: missing -- before the rotbeam arguments" >&2; exit 2; }
shift
rotbeam=${ROTBEAM:-rotbeam}
cpus=${CPUS:-2}
sbatch=${SBATCH:-sbatch}
timings=${TIMINGS:+--timings $TIMINGS}
args=$(printf ' %q' "$@")
mkdir -p "$out"
task="$rotbeam$args --shard \$SLURM_ARRAY_TASK_ID/$n --jobs \$SLURM_CPUS_PER_TASK $timings"
task+=" --out $out/shard-\$SLURM_ARRAY_TASK_ID"
array=$($sbatch --parsable --array=1-"$n" --cpus-per-task="$cpus" --job-name=rotbeam-shard \
    --output="$out/shard-%a.log" "${options[@]}" --wrap "$task")
merge="$rotbeam merge $(for i in $(seq 1 "$n"); do printf '%s ' "$out/shard-$i"; done)--out $out/merged"
$sbatch --parsable --dependency=afterany:"${array%%;*}" --job-name=rotbeam-merge \
    --output="$out/merge.log" "${options[@]}" --wrap "$merge"
echo "submitted: $n shards (job ${array%%;*}) and the merge → $out/merged; a failed task I:" \
    "$sbatch --array=I --cpus-per-task=$cpus ${options[*]} --wrap \"$task\"" >&2
