#!/usr/bin/env bash
# `mpirun -np 3 rotbeam suite --quick` (the MPI build, docs/distributed-runs.md, "MPI") against one
# process: the same result files (scripts/compare-results.py: equal JSON apart from the timing
# fields), no work folder left behind, and rank 0 alone printing the output's summary. --quick has
# the 20 runs, the split studies' runs, the whole studies and the timed speed-accuracy study, so
# every kind of unit goes through the ranks. --oversubscribe: three ranks on a machine with fewer
# cores. As root (CI's container) Open MPI needs OMPI_ALLOW_RUN_AS_ROOT and its confirmation.
# Usage: mpi_suite.sh ROTBEAM COMPARE_RESULTS_PY MPIEXEC
set -u
rotbeam=$1
compare=$2
mpiexec=$3
. "$(dirname "$0")/scratch.sh"
. "$(dirname "$0")/results_check.sh"
if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

"$rotbeam" suite --quick --jobs 1 --out "$work/one" >/dev/null 2>"$work/err1.txt" ||
    fail "one process failed: $(tail -1 "$work/err1.txt")"
"$mpiexec" --oversubscribe -np 3 "$rotbeam" suite --quick --out "$work/ranks" \
    >"$work/out3.txt" 2>"$work/err3.txt" || fail "mpirun -np 3 failed: $(tail -3 "$work/err3.txt")"
same "$work/one" "$work/ranks" "mpirun -np 3"
complete_files "$work/ranks" "mpirun -np 3"
[ -e "$work/ranks/.rotbeam-ranks" ] && fail "the ranks' work folder was left in the output"
grep -q "units on 3 ranks" "$work/out3.txt" || fail "no 'units on 3 ranks' line from rank 0"
n=$(grep -c "units on 3 ranks" "$work/out3.txt")
[ "$n" -eq 1 ] || fail "the summary line printed $n times (rank 0 only)"

[ $failures -eq 0 ] && echo "mpi_suite: mpirun -np 3 = one process"
exit $((failures > 0))
