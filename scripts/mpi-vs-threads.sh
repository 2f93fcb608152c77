#!/usr/bin/env bash
# Two ranks against two threads on one machine (docs/distributed-runs.md, "Two ranks on the
# 2-core machine"): each study given, full size, as one process with two threads
# (`study NAME --shard 1/1 --jobs 2`, then `merge`: the suite's `--jobs 2` path for a study's runs)
# and as `mpirun -np 2 rotbeam-mpi study NAME` (which plans, makes, merges and combines), the two
# alternated ROUNDS times (A B A B ...) so that a change of the machine's load falls on both.
# Prints one line per run (wall seconds, load average before..after), then per study the medians
# and their ratio, and checks that both outputs are the same results (scripts/compare-results.py).
#
# usage: scripts/mpi-vs-threads.sh [ROUNDS] [STUDY...]   (default: 3 convergence extremes)
# Environment: ROTBEAM, ROTBEAM_MPI (default: build/release/cases/runner/rotbeam[-mpi]), MPIRUN
# (default mpirun), WORK (a scratch folder, default a new one under /tmp, removed at the end).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
shift || true
studies=("$@")
[ ${#studies[@]} -gt 0 ] || studies=(convergence extremes)
rotbeam=$(realpath "${ROTBEAM:-build/release/cases/runner/rotbeam}")
rotbeam_mpi=$(realpath "${ROTBEAM_MPI:-build/release/cases/runner/rotbeam-mpi}")
mpirun=${MPIRUN:-mpirun}
work=${WORK:-$(mktemp -d /tmp/mpi-vs-threads.XXXXXX)}
mkdir -p "$work"
[ -n "${WORK:-}" ] || trap 'rm -rf "$work"' EXIT
if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
load() { cut -d' ' -f1 /proc/loadavg; }
# timed LOG COMMAND...: runs it with no output, appends its wall seconds to LOG, prints a line.
timed() {
    local log=$1 l0 t0 t1
    shift
    l0=$(load)
    t0=$(date +%s.%N)
    "$@" >/dev/null 2>"$work/stderr.txt" || { tail -3 "$work/stderr.txt" >&2; exit 1; }
    t1=$(date +%s.%N)
    python3 -c "print(f'{$t1 - $t0:.2f}')" >>"$log"
    echo "  $(basename "$log" .txt): $(tail -1 "$log") s (load $l0 .. $(load))"
}
threads() {  # threads STUDY OUT
    "$rotbeam" study "$1" --shard 1/1 --jobs 2 --out "$2-shard" &&
        "$rotbeam" merge "$2-shard" --out "$2"
}
ranks() {  # ranks STUDY OUT
    "$mpirun" -np 2 "$rotbeam_mpi" study "$1" --out "$2"
}
for study in "${studies[@]}"; do
    echo "$study: $rounds rounds, A = --jobs 2 + merge, B = mpirun -np 2"
    for r in $(seq "$rounds"); do
        rm -rf "$work/a-$study" "$work/a-$study-shard" "$work/b-$study"
        timed "$work/$study-threads.txt" threads "$study" "$work/a-$study"
        timed "$work/$study-ranks.txt" ranks "$study" "$work/b-$study"
    done
    python3 scripts/compare-results.py "$work/a-$study" "$work/b-$study" >/dev/null ||
        { echo "$study: the two outputs differ" >&2; exit 1; }
    python3 - "$study" "$work/$study-threads.txt" "$work/$study-ranks.txt" <<'PY'
import statistics, sys
a = [float(x) for x in open(sys.argv[2])]
b = [float(x) for x in open(sys.argv[3])]
ma, mb = statistics.median(a), statistics.median(b)
print(f"{sys.argv[1]}: median --jobs 2 + merge {ma:.2f} s, mpirun -np 2 {mb:.2f} s, "
      f"ratio {mb / ma:.3f} ({100 * (mb / ma - 1):+.1f} %); outputs identical")
PY
done
