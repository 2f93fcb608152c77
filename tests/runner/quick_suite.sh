#!/usr/bin/env bash
# `rotbeam suite --quick --jobs 2` once, into OUT (removed first), for the checks that read its
# results and report instead of running the same suite again (test_report_complete,
# test_suite_resume, test_report_full_disk, test_mpi_suite; docs/quality-checks.md, "Time"). The
# ctest fixture `quick_suite`.
# Usage: quick_suite.sh ROTBEAM OUT
set -u
# One timed repeat per measurement (runs/timing.hpp, timing_repeats): the suite's timed study
# (speed-accuracy) computes its errors, counters and result comparisons as before, and times each
# point once instead of a median of 3 or more; the times are the one thing the tests that read
# this suite do not compare (scripts/compare-results.py), and the repeats were a quarter of the
# suite's CPU time (docs/quality-checks.md, Time).
export ROTBEAM_TIMING_REPEATS=1
rotbeam=$1
out=$2
rm -rf "$out"
mkdir -p "$(dirname "$out")"
if ! "$rotbeam" suite --quick --jobs 2 --out "$out" >"$out.log" 2>&1; then
    echo "FAIL: suite --quick --jobs 2 failed: $(tail -3 "$out.log")"
    rm -rf "$out"
    exit 1
fi
echo "quick suite written to $out"
