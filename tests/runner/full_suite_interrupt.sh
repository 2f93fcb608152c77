#!/usr/bin/env bash
# Nothing half-written by the whole suite's runs (docs/durability.md): `rotbeam suite` over the
# whole catalog (not --quick: its dynamic and modal cases write CSV histories and other files the
# quick suite's do not) stopped early, by SIGINT once 2 runs are written, SIGKILL at 4 and SIGTERM
# at 6, and under a file size limit of 1 KiB (ulimit -f, the EFBIG of a full disk): exit 128 +
# signal or 4 with one line naming the file, and only complete files left (complete_files). A
# stop costs only the runs before it (the first runs in catalog order: the static bend-45's);
# resuming the whole suite to compare it with an uninterrupted one would cost two whole suites
# (docs/durability.md, "What is tested").
# Usage: full_suite_interrupt.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work, fail and failures; complete_files and full_disk.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
# Background jobs in their own process group: a non-interactive shell would otherwise start
# them with SIGINT ignored, which rotbeam (rightly) leaves ignored.
set -m

runs_in() { find "$1/runs" -name '*.json' 2>/dev/null | wc -l; }

for stop in INT:2 KILL:4 TERM:6; do
    signal=${stop%:*} n=${stop#*:} dir="$work/$signal"
    start=$SECONDS
    "$rotbeam" suite --no-studies --jobs 2 --out "$dir" >/dev/null 2>"$work/err.txt" &
    pid=$!
    while [ "$(runs_in "$dir")" -lt "$n" ] && kill -0 $pid 2>/dev/null; do sleep 0.05; done
    kill -s "$signal" $pid 2>/dev/null
    wait $pid
    code=$?
    expected=$((128 + $(kill -l "$signal")))
    [ $code -eq $expected ] || fail "SIG$signal: exit $code, expected $expected: $(tail -1 "$work/err.txt")"
    if [ "$signal" = KILL ]; then
        complete_files "$dir" "the whole suite after SIG$signal" temporaries-allowed
    else
        grep -q "stopped by SIG$signal" "$work/err.txt" || fail "SIG$signal: no line saying so"
        complete_files "$dir" "the whole suite after SIG$signal"
    fi
    echo "SIG$signal at $n runs: exit $code after $((SECONDS - start)) s, $(runs_in "$dir") runs" \
        "and $(find "$dir" -type f | wc -l) files left"
done

dir="$work/full"
full_disk 1 "$dir" "the whole suite" "$rotbeam" suite --no-studies --jobs 2 --out "$dir"
echo "ulimit -f 1: ${last#rotbeam: $dir/}"

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "whole suite stopped by SIGINT/SIGKILL/SIGTERM and by a file size limit: only complete files"
