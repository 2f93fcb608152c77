#!/usr/bin/env bash
# Nothing half-written by `rotbeam sweep` (docs/durability.md), on the example sweep
# cases/sweeps/rollup-load-elements.yaml (24 runs of ~25 ms of CPU each, ~1 CPU-s a sweep):
# - uninterrupted with --jobs 2: the reference;
# - with --jobs 1 into another folder, stopped by SIGKILL once 2 runs are written, rerun and
#   stopped by SIGTERM at 8, rerun and stopped by SIGINT at 16, then rerun to its end: each stop
#   exits 128 + signal (SIGINT/SIGTERM with one line saying so) and leaves only complete files
#   (after SIGKILL: hidden temporaries at most, which the next sweep removes); a rerun leaves the
#   finished runs' files untouched;
# - under a file size limit (ulimit -f, the EFBIG of a full disk) of 4 KiB, where no run file
#   fits, then of 8 KiB, where the runs fit and the sweep table does not: exit 4 with one line
#   naming the file, nothing cut short, then resumed to its end;
# and both resumed sweeps have the results of the uninterrupted one (scripts/compare-results.py)
# and its sweep.csv byte for byte.
# Usage: sweep_interrupt.sh ROTBEAM COMPARE_RESULTS_PY SOURCE_DIR
set -u
# rotbeam, compare; work, fail and failures; same, complete_files and full_disk.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
file=$3/cases/sweeps/rollup-load-elements.yaml
# Background jobs in their own process group: a non-interactive shell would otherwise start
# them with SIGINT ignored, which rotbeam (rightly) leaves ignored.
set -m

runs_in() { find "$1/runs" -maxdepth 1 -name '*.json' 2>/dev/null | wc -l; }

"$rotbeam" sweep "$file" --jobs 2 --out "$work/ref" >/dev/null 2>"$work/err.txt" ||
    fail "the uninterrupted sweep failed: $(tail -1 "$work/err.txt")"
total=$(runs_in "$work/ref")
[ "$total" -eq 24 ] || fail "the uninterrupted sweep wrote $total runs, expected 24"

# stop_at SIGNAL RUNS: the --jobs 1 sweep into $dir, stopped by SIGNAL once RUNS run files are
# written. A sweep that ends before the signal fails the check: the stop was not tested.
dir="$work/stopped"
stop_at() {
    local signal=$1 runs=$2 before
    before=$(cd "$dir/runs" 2>/dev/null && stat -c '%n %y' -- *.json | sort)
    "$rotbeam" sweep "$file" --jobs 1 --out "$dir" >/dev/null 2>"$work/err.txt" &
    local pid=$!
    while [ "$(runs_in "$dir")" -lt "$runs" ] && kill -0 $pid 2>/dev/null; do sleep 0.01; done
    kill -s "$signal" $pid 2>/dev/null
    wait $pid
    local code=$? expected=$((128 + $(kill -l "$signal")))
    if [ $code -ne $expected ]; then
        fail "SIG$signal at $runs runs: exit $code, expected $expected: $(tail -1 "$work/err.txt")"
    fi
    if [ "$signal" = KILL ]; then
        complete_files "$dir" "the sweep after SIG$signal" temporaries-allowed
    else
        grep -q "stopped by SIG$signal" "$work/err.txt" || fail "SIG$signal: no line saying so"
        complete_files "$dir" "the sweep after SIG$signal"
    fi
    [ -e "$dir/sweep.csv" ] && fail "SIG$signal at $runs runs: the sweep table was written"
    while read -r name stamp; do
        [ -z "$name" ] && continue
        [ "$(stat -c '%y' "$dir/runs/$name")" = "$stamp" ] || fail "SIG$signal: finished run redone: $name"
    done <<<"$before"
    echo "SIG$signal at $runs runs: exit $code, $(runs_in "$dir") of $total runs kept"
}
stop_at KILL 2
stop_at TERM 8
stop_at INT 16
"$rotbeam" sweep "$file" --jobs 1 --out "$dir" >/dev/null 2>"$work/err.txt" ||
    fail "the stopped sweep, resumed: $(tail -1 "$work/err.txt")"
complete_files "$dir" "the stopped sweep, resumed"
same "$work/ref" "$dir" "the stopped and resumed --jobs 1 sweep"
cmp -s "$work/ref/sweep.csv" "$dir/sweep.csv" || fail "the resumed sweep's sweep.csv differs"

# A full disk: every run file (~5 KiB) is refused at 4 KiB; at 8 KiB they are written and the
# sweep table (sweep.csv, ~11 KiB) is refused.
dir="$work/full"
for kib in 4 8; do
    full_disk $kib "$dir" "the sweep" "$rotbeam" sweep "$file" --jobs 2 --out "$dir"
    echo "ulimit -f $kib: $(runs_in "$dir") runs kept: ${last#rotbeam: $dir/}"
done
[ "$(runs_in "$dir")" -eq "$total" ] || fail "ulimit -f 8: $(runs_in "$dir") of $total runs written"
grep -q "^rotbeam: $dir/sweep.csv: " <<<"$last" || fail "ulimit -f 8: not the sweep table: $last"
"$rotbeam" sweep "$file" --jobs 2 --out "$dir" >/dev/null 2>"$work/err.txt" ||
    fail "the sweep resumed after a full disk: $(tail -1 "$work/err.txt")"
complete_files "$dir" "the sweep resumed after a full disk"
same "$work/ref" "$dir" "the sweep resumed after a full disk"
cmp -s "$work/ref/sweep.csv" "$dir/sweep.csv" || fail "the sweep.csv resumed after a full disk differs"

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "sweep stopped by SIGKILL/SIGTERM/SIGINT and by a file size limit: only complete files," \
    "resumed to the uninterrupted results"
