#!/usr/bin/env bash
# `mpirun --oversubscribe -np 3 rotbeam ...` (the MPI build, docs/distributed-runs.md, "MPI")
# against one process, on one job of each kind of unit: the runs of `suite --quick --no-studies`
# (20 case runs, the summaries and the report), the quick convergence study (242 runs and the
# combine step) and the quick joined-beam modal study (one whole study): the same result files
# (scripts/compare-results.py: equal JSON apart from the timing fields), no work folder left
# behind, rank 0 alone printing the summary. Not `suite --quick` whole: twice that (one process
# and the ranks) is ~110 s of CPU and twice the timed speed study, too much for CI.
# --oversubscribe: three ranks on a machine with fewer cores. As root (CI's container) Open MPI
# needs OMPI_ALLOW_RUN_AS_ROOT and its confirmation.
# Usage: mpi_suite.sh ROTBEAM COMPARE_RESULTS_PY MPIEXEC
set -u
mpiexec=$3
# rotbeam, compare; work (a scratch folder), fail and failures; same and complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

# Each job once in one process and once over three ranks: the same files, no work folder left,
# the summary line from rank 0 only.
check() {  # check NAME ROTBEAM_ARGUMENTS...
    local name=$1
    shift
    "$rotbeam" "$@" --out "$work/one-$name" >/dev/null 2>"$work/err1.txt" ||
        fail "$name: one process failed: $(tail -1 "$work/err1.txt")"
    "$mpiexec" --oversubscribe -np 3 "$rotbeam" "$@" --out "$work/ranks-$name" \
        >"$work/out3.txt" 2>"$work/err3.txt" ||
        fail "$name: mpirun -np 3 failed: $(tail -3 "$work/err3.txt")"
    same "$work/one-$name" "$work/ranks-$name" "$name over 3 ranks"
    complete_files "$work/ranks-$name" "$name over 3 ranks"
    [ -e "$work/ranks-$name/.rotbeam-ranks" ] && fail "$name: the work folder was left in the output"
    n=$(grep -c "units on 3 ranks" "$work/out3.txt")
    [ "$n" -eq 1 ] || fail "$name: the summary line printed $n times (rank 0 only)"
}
check runs suite --quick --no-studies --jobs 1
check convergence study convergence --quick
check modal study joined-beam-modal --quick

[ $failures -eq 0 ] && echo "mpi_suite: mpirun -np 3 = one process (case runs, a split study, a whole study)"
exit $((failures > 0))
