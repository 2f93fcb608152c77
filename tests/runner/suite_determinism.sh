#!/usr/bin/env bash
# The whole suite is deterministic (docs/durability.md): `rotbeam suite` (every catalog case with
# every combination, every study, the report) run twice, with --jobs 1 and with --jobs 2, writes
# complete files only and the same results by scripts/compare-results.py (equal JSON apart from
# the listed timing fields). test_suite_resume checks the same of the quick suite on every
# change; this one, the whole suite, takes two whole suites (label `long`, not in CI).
# Usage: suite_determinism.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work (a scratch folder), fail and failures; same and complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"

for jobs in 1 2; do
    start=$(date +%s)
    "$rotbeam" suite --jobs $jobs --out "$work/jobs$jobs" >/dev/null 2>"$work/err.txt" ||
        fail "suite --jobs $jobs failed: $(tail -3 "$work/err.txt")"
    complete_files "$work/jobs$jobs" "suite --jobs $jobs"
    echo "suite --jobs $jobs: $(ls "$work/jobs$jobs/runs" | grep -c '\.json$') runs," \
        "$(find "$work/jobs$jobs" -name '*.json' | wc -l) JSON files in $(($(date +%s) - start)) s"
done
same "$work/jobs1" "$work/jobs2" "the --jobs 2 suite"

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "whole suite: --jobs 1 = --jobs 2 ($(find "$work/jobs1" -type f | wc -l) files compared)"
