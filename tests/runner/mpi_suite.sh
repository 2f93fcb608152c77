#!/usr/bin/env bash
# `mpirun --oversubscribe -np 3 rotbeam-mpi suite --quick` (docs/distributed-runs.md, "MPI") against
# one process: the whole quick suite — its case runs, the split studies' runs and combine steps,
# the whole studies and the timed one (speed-accuracy, made by rank 0 alone after every other
# unit), the summaries and the report — then a sweep file's runs and table. The same result files
# (scripts/compare-results.py: equal JSON apart from the timings and what is computed from them),
# no work folder left behind, rank 0 alone printing the summary.
# --oversubscribe: three ranks on a machine with fewer cores. As root (CI's container) Open MPI
# needs OMPI_ALLOW_RUN_AS_ROOT and its confirmation.
# Usage: mpi_suite.sh ROTBEAM COMPARE_RESULTS_PY MPIEXEC ROTBEAM_MPI JOBS2_SUITE
# JOBS2_SUITE: `rotbeam suite --quick --jobs 2` of the same program (the ctest fixture quick_suite),
# the one-process side of the suite's comparison: the command this test would otherwise run itself
# (a whole quick suite, ~105 CPU-s; docs/quality-checks.md, Time).
set -u
mpiexec=$3
rotbeam_mpi=$4
jobs2=$5
# rotbeam, compare; work (a scratch folder), fail and failures; same and complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
# One timed repeat per measurement, as in the fixture (quick_suite.sh): the timings are not
# compared. mpirun passes its environment to the ranks it starts on this machine.
export ROTBEAM_TIMING_REPEATS=1
if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
sweep_file=$(cd "$(dirname "$0")/../.." && pwd)/cases/sweeps/rollup-load-elements.yaml

# Each job over three ranks (one thread each, the default under mpirun) against one process (the
# static program, two threads: `--jobs 2 --out ONE`): the same files, no work folder left, the
# summary line from rank 0 only. ONE is made here unless given (the suite's is the fixture's).
check() {  # check NAME ONE|"" ROTBEAM_ARGUMENTS...
    local name=$1 one=$2
    shift 2
    if [ -z "$one" ]; then
        one="$work/one-$name"
        "$rotbeam" "$@" --jobs 2 --out "$one" >/dev/null 2>"$work/err1.txt" ||
            fail "$name: one process failed: $(tail -1 "$work/err1.txt")"
    fi
    "$mpiexec" --oversubscribe -np 3 "$rotbeam_mpi" "$@" --out "$work/ranks-$name" \
        >"$work/out3.txt" 2>"$work/err3.txt" ||
        fail "$name: mpirun -np 3 failed: $(tail -3 "$work/err3.txt")"
    same "$one" "$work/ranks-$name" "$name over 3 ranks"
    complete_files "$work/ranks-$name" "$name over 3 ranks"
    [ -e "$work/ranks-$name/.rotbeam-ranks" ] && fail "$name: the work folder was left in the output"
    n=$(grep -c "units on 3 ranks" "$work/out3.txt")
    [ "$n" -eq 1 ] || fail "$name: the summary line printed $n times (rank 0 only)"
}
if [ -f "$jobs2/index.md" ]; then
    check suite "$jobs2" suite --quick
else
    fail "no --jobs 2 suite in $jobs2 (the fixture quick_suite failed?)"
fi
check sweep "" sweep "$sweep_file"

[ $failures -eq 0 ] && echo "mpi_suite: mpirun -np 3 = one process (suite --quick whole, a sweep)"
exit $((failures > 0))
