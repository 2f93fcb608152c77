#!/usr/bin/env bash
# Nothing half-written, resumes exactly, deterministic (docs/durability.md). Over `rotbeam suite
# --quick` (its static runs and every study in its quick form; its runs alone where said):
# - `--jobs 2` gives the same results as `--jobs 1` (scripts/compare-results.py: equal JSON apart
#   from the listed timing fields);
# - a suite stopped by SIGKILL, SIGINT or SIGTERM, early (among the runs) or late (in the
#   studies), leaves only complete files and no temporary (after SIGKILL: none once resumed), exits 128 + signal with one line for
#   SIGINT/SIGTERM, keeps its finished runs untouched on resume, and resumes to the same results;
# - a suite and a `run` that hit a file size limit (ulimit -f, the EFBIG of a full disk) exit 4
#   naming the file, leave no partial file, and the suite then resumes to the same results;
# - a `run` stopped by SIGINT or SIGTERM writes nothing, and one stopped by SIGKILL no partial file;
# - every folder checked (complete_files) holds no file cut short: JSON that parses, text files
#   that end with their newline, CSV rows of the header's width, PNGs that end with IEND.
# Usage: suite_resume.sh ROTBEAM COMPARE_RESULTS_PY JOBS2_SUITE
# JOBS2_SUITE: `rotbeam suite --quick --jobs 2` of the same program (the ctest fixture quick_suite).
set -u
jobs2=$3
# One timed repeat per measurement, as in the fixture (quick_suite.sh): the timings are not compared.
export ROTBEAM_TIMING_REPEATS=1
# rotbeam, compare; work (a scratch folder), fail and failures; same and complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
# Background jobs in their own process group: a non-interactive shell would otherwise start
# them with SIGINT ignored, which rotbeam (rightly) leaves ignored.
set -m

# Reference: one uninterrupted suite on two threads, the fixture's. The suite stopped late (in its
# studies) runs and resumes on one thread, so that comparing it with the reference checks both
# that a resumed suite equals an uninterrupted one and that --jobs 1 equals --jobs 2 (a difference
# from either fails it; each needs ~55 s of CPU for a whole quick suite, so one suite does both).
# The studies cost most of the quick suite, so the early stops and the full disk use the runs
# alone (--no-studies, ~5 s) against a reference of their own, on one thread.
[ -f "$jobs2/index.md" ] || fail "no --jobs 2 suite in $jobs2 (the fixture quick_suite failed?)"
total=$(ls "$jobs2/runs" 2>/dev/null | grep -c '\.json$')
[ "$total" -ge 16 ] || fail "reference suite wrote $total runs"
"$rotbeam" suite --quick --no-studies --jobs 1 --out "$work/ref-runs" >/dev/null 2>&1 ||
    fail "reference suite (runs) failed"

# Interrupted: SIGKILL and SIGTERM once a few runs are written, SIGINT once the studies write.
interrupt() {  # interrupt SIGNAL WHEN DIR REFERENCE JOBS [FLAGS]
    local signal=$1 when=$2 dir=$3 reference=$4 jobs=$5 flags=${6:-}
    "$rotbeam" suite --quick $flags --jobs $jobs --out "$dir" >"$work/out.txt" 2>"$work/err.txt" &
    local pid=$!
    for _ in $(seq 1 3000); do
        if [ "$when" = early ]; then
            [ "$(ls "$dir/runs" 2>/dev/null | grep -c '\.json$')" -ge 3 ] && break
        else
            ls "$dir"/study-*.json >/dev/null 2>&1 && break
        fi
        kill -0 $pid 2>/dev/null || break
        sleep 0.02
    done
    kill -s "$signal" $pid 2>/dev/null
    wait $pid
    local code=$?
    if [ -f "$dir/index.md" ]; then
        echo "note: the suite finished before $signal ($when)"
        same "$reference" "$dir" "the suite (--jobs $jobs) that finished before SIG$signal"
        return
    fi
    case $signal in
    KILL) [ $code -eq 137 ] || fail "SIGKILL: exit $code" ;;
    INT | TERM)
        local expected=$((128 + $(kill -l "$signal")))
        [ $code -eq $expected ] || fail "SIG$signal: exit $code, expected $expected"
        grep -q "stopped by SIG$signal" "$work/err.txt" || fail "SIG$signal: no line saying so"
        ;;
    esac
    if [ "$signal" = KILL ]; then
        complete_files "$dir" "after SIG$signal ($when)" temporaries-allowed
    else
        complete_files "$dir" "after SIG$signal ($when)"
    fi
    local before finished
    finished=$(ls "$dir/runs" | grep -c '\.json$')
    before=$(cd "$dir/runs" && stat -c '%n %y' *.json | sort)
    "$rotbeam" suite --quick $flags --jobs $jobs --out "$dir" >/dev/null 2>&1 ||
        fail "resume after SIG$signal failed"
    complete_files "$dir" "resumed after SIG$signal ($when)"
    while read -r name stamp; do
        [ "$(stat -c '%y' "$dir/runs/$name")" = "$stamp" ] || fail "finished run redone: $name"
    done <<<"$before"
    same "$reference" "$dir" \
        "the suite (--jobs $jobs) resumed after SIG$signal ($when, $finished of $total runs)"
    echo "SIG$signal ($when, --jobs $jobs): stopped with exit $code after $finished of $total runs," \
        "resumed"
}
interrupt KILL early "$work/kill" "$work/ref-runs" 2 --no-studies
interrupt TERM early "$work/term" "$work/ref-runs" 2 --no-studies
interrupt INT late "$work/int" "$jobs2" 1

# A file size limit of 8 KiB: the run results (tens of KiB) cannot be written.
(
    ulimit -f 8
    exec "$rotbeam" suite --quick --no-studies --jobs 2 --out "$work/full" >/dev/null 2>"$work/err.txt"
)
code=$?
[ $code -eq 4 ] || fail "suite on a full disk: exit $code, expected 4"
grep -q "$work/full/.*File too large\|$work/full/.*file size limit" "$work/err.txt" ||
    fail "suite on a full disk: the message does not name the file: $(head -c 300 "$work/err.txt")"
complete_files "$work/full" "suite on a full disk"
"$rotbeam" suite --quick --no-studies --jobs 2 --out "$work/full" >/dev/null 2>&1 ||
    fail "resume after a full disk failed"
same "$work/ref-runs" "$work/full" "the suite resumed after a full disk"

# `run`: a file size limit, then SIGINT and SIGTERM during a dynamic run; nothing is written.
mkdir -p "$work/run"
(
    ulimit -f 8
    exec "$rotbeam" run cantilever-moment --json "$work/run/r.json" --out "$work/run" \
        >/dev/null 2>"$work/err.txt"
)
code=$?
[ $code -eq 4 ] || fail "run on a full disk: exit $code, expected 4"
grep -q "$work/run/r.json" "$work/err.txt" || fail "run on a full disk: file not named"
[ -z "$(ls -A "$work/run")" ] || fail "run on a full disk left: $(ls -A "$work/run")"
for signal in INT TERM; do
    "$rotbeam" run joined-beam-dead --out "$work/run" >/dev/null 2>"$work/err.txt" &
    pid=$!
    sleep 0.5
    kill -s $signal $pid
    wait $pid
    code=$?
    expected=$((128 + $(kill -l $signal)))
    if [ -n "$(ls -A "$work/run")" ] && [ $code -eq 0 ]; then
        echo "note: the run finished before SIG$signal"
    else
        [ $code -eq $expected ] || fail "run, SIG$signal: exit $code, expected $expected"
        [ -z "$(ls -A "$work/run")" ] || fail "run, SIG$signal left: $(ls -A "$work/run")"
    fi
done
# `run` stopped by SIGKILL: its hidden temporaries at most, never a partial result (a result written
# before the signal is complete).
rm -rf "$work/run-kill"
mkdir -p "$work/run-kill"
"$rotbeam" run joined-beam-dead --out "$work/run-kill" >/dev/null 2>&1 &
pid=$!
sleep 0.5
kill -s KILL $pid
wait $pid
code=$?
if [ $code -eq 0 ]; then
    echo "note: the run finished before SIGKILL"
else
    [ $code -eq 137 ] || fail "run, SIGKILL: exit $code, expected 137"
    complete_files "$work/run-kill" "run after SIGKILL" temporaries-allowed
fi
# And an uninterrupted run is the same twice (the JSON and the CSV history of a dynamic run).
"$rotbeam" run joined-beam-dead --out "$work/run/a" >/dev/null 2>&1 || fail "run failed"
"$rotbeam" run joined-beam-dead --out "$work/run/b" >/dev/null 2>&1 || fail "run failed"
"$compare" "$work/run/a" "$work/run/b" >/dev/null || fail "two runs differ"
cmp -s "$work/run/a/"*.csv "$work/run/b/"*.csv || fail "two runs' CSV histories differ"

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "suite resume: --jobs 1 = --jobs 2; stopped by SIGKILL/SIGTERM/SIGINT and by a file size" \
    "limit, resumed to the same results; run leaves no partial file when stopped"
