#!/usr/bin/env bash
# The whole suite is deterministic and resumes exactly (docs/durability.md): `rotbeam suite`
# (every catalog case with every combination, every study, the report) run uninterrupted with
# --jobs 2, and again with --jobs 1 into another folder, stopped there by SIGKILL once an eighth of
# the runs are written, rerun and stopped by SIGTERM at half of them, rerun and stopped by SIGINT
# in the studies (every run written, at the next new file), then rerun to its end. Every stop
# leaves only complete files (after SIGKILL: hidden temporaries at most, which the next suite
# removes), and the resumed --jobs 1 suite has the same results as the uninterrupted --jobs 2 one
# by scripts/compare-results.py (equal JSON apart from the listed timing fields): a resume that
# changed a result and a result that depends on --jobs both show as a difference. Two whole suites
# (label `long`, not in CI); test_suite_resume checks the quick suite on every change.
# Usage: suite_determinism.sh ROTBEAM COMPARE_RESULTS_PY [SUITE_OPTION...]
# (options such as --quick or --cases GLOB run the same checks on a part of the suite).
set -u
# One timed repeat per measurement (runs/timing.hpp, timing_repeats), as in the quick suite's
# fixture: the full suite's timed study (speed-accuracy) times each point once instead of a median
# of several. Its errors, counters and results are computed as before; the times and what derives
# from them (ratios, Pareto fronts, repeat counts) are what scripts/compare-results.py leaves out.
# Uncapped, the --jobs 2 suite alone had used 38.8 CPU-minutes, still in that study, at 84 min
# wall on the shared machine (2026-11-27), and the test could not end within its timeout.
export ROTBEAM_TIMING_REPEATS=1
# rotbeam, compare; work (a scratch folder), fail and failures; same and complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
shift 2
suite_options=("$@")
# Background jobs in their own process group: a non-interactive shell would otherwise start
# them with SIGINT ignored, which rotbeam (rightly) leaves ignored.
set -m

runs_in() { find "$1/runs" -maxdepth 1 -name '*.json' 2>/dev/null | wc -l; }
files_in() { find "$1" -type f 2>/dev/null | wc -l; }

start=$SECONDS
"$rotbeam" suite "${suite_options[@]}" --jobs 2 --out "$work/jobs2" >/dev/null 2>"$work/err.txt" ||
    fail "suite --jobs 2 failed: $(tail -3 "$work/err.txt")"
complete_files "$work/jobs2" "suite --jobs 2"
total=$(runs_in "$work/jobs2")
echo "suite --jobs 2: $total runs, $(find "$work/jobs2" -name '*.json' | wc -l) JSON files" \
    "in $((SECONDS - start)) s"

# stop_at SIGNAL RUNS: the --jobs 1 suite, into its folder, stopped by SIGNAL once RUNS run files
# are written and the folder holds a file more than then.
dir="$work/jobs1"
stop_at() {
    local signal=$1 runs=$2 start=$SECONDS n
    "$rotbeam" suite "${suite_options[@]}" --jobs 1 --out "$dir" >/dev/null 2>"$work/err.txt" &
    local pid=$!
    while [ "$(runs_in "$dir")" -lt "$runs" ] && kill -0 $pid 2>/dev/null; do sleep 0.05; done
    n=$(($(files_in "$dir") + 1))
    while [ "$(files_in "$dir")" -lt "$n" ] && kill -0 $pid 2>/dev/null; do sleep 0.02; done
    kill -s "$signal" $pid 2>/dev/null
    wait $pid 2>/dev/null
    local code=$?
    if [ $code -eq 0 ]; then
        echo "note: suite finished before SIG$signal ($((SECONDS - start)) s)"
    elif [ $code -ne $((128 + $(kill -l "$signal"))) ]; then
        fail "suite --jobs 1, SIG$signal: exit $code: $(tail -1 "$work/err.txt")"
    fi
    if [ "$signal" = KILL ]; then
        complete_files "$dir" "suite after SIG$signal" temporaries-allowed
    else
        complete_files "$dir" "suite after SIG$signal"
    fi
    echo "suite --jobs 1: SIG$signal at $(runs_in "$dir") of $total runs after" \
        "$((SECONDS - start)) s, exit $code"
}
stop_at KILL $(((total + 7) / 8))
stop_at TERM $((total / 2))
stop_at INT "$total"
start=$SECONDS
"$rotbeam" suite "${suite_options[@]}" --jobs 1 --out "$dir" >/dev/null 2>"$work/err.txt" ||
    fail "suite --jobs 1, resumed: $(tail -3 "$work/err.txt")"
complete_files "$dir" "suite --jobs 1, resumed"
echo "suite --jobs 1 resumed to its end in $((SECONDS - start)) s"
same "$work/jobs2" "$dir" "the stopped and resumed --jobs 1 suite"

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "suite ${suite_options[*]:-(whole)}: stopped 3 times and resumed with --jobs 1 = uninterrupted --jobs 2" \
    "($(find "$dir" -type f | wc -l) files compared)"

# The whole suite's report, not only the quick one, is complete and consistent: every linked file
# exists, every table's numbers parse, no NaN or absurd value in its results and data files
# (tests/reports/check_report.py, which test_report_complete runs on the quick suite's report).
for d in "$work/jobs2" "$dir"; do
    python3 "$(dirname "$0")/../reports/check_report.py" "$d" ||
        { echo "FAIL: the whole suite's report in $(basename "$d") is incomplete or inconsistent"; exit 1; }
done
