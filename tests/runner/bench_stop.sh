#!/usr/bin/env bash
# `rotbeam bench` stopped while one of its timed runs (rotbeam itself, run as a child) is running
# (docs/durability.md): the child is killed and waited for with rotbeam, so no process of the bench
# survives it, its JSON is absent or whole, and the children's report files (TMPDIR) are gone.
# Before, the timed runs were started outside the children's registry: SIGTERM, SIGINT or SIGHUP
# sent to rotbeam alone never reached them and they outlived the bench.
# The timed run is made to last: the start-up timing runs `rotbeam check` on the catalog case
# cantilever-moment (after one `rotbeam --version`), and the catalog given to the bench holds that
# case as a named pipe, which the child's open blocks on, as long as the test wants. Each stop
# waits until that child runs, signals rotbeam and looks for survivors in rotbeam's process group.
# Usage: bench_stop.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work, fail and failures; complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
# Background jobs in their own process group: SIGINT would otherwise be ignored (set by the shell).
set -m
mkdir "$work/cases"
mkfifo "$work/cases/cantilever-moment.yaml"

# The child of rotbeam $1 that runs `check` (its arguments: /proc/self/exe check PATH), if any.
check_child() {
    local c
    for c in $(pgrep -P "$1"); do
        tr '\0' ' ' <"/proc/$c/cmdline" 2>/dev/null | grep -q ' check ' && echo "$c" && return
    done
}

for signal in TERM INT HUP; do
    dir="$work/$signal"
    mkdir -p "$dir/tmp" "$dir/out"
    ROTBEAM_CASES="$work/cases" TMPDIR="$dir/tmp" "$rotbeam" bench --quick --repeats 1 \
        --targets long-run --json "$dir/out/bench.json" >/dev/null 2>"$work/err.txt" &
    pid=$!
    child=""
    while [ -z "$child" ] && kill -0 $pid 2>/dev/null; do
        child=$(check_child $pid)
        [ -n "$child" ] || sleep 0.01
    done
    if [ -z "$child" ]; then
        fail "SIG$signal: the bench ended before its timed run: $(tail -1 "$work/err.txt")"
        continue
    fi
    kill -s $signal $pid
    wait $pid
    code=$?
    if [ $code -ne $((128 + $(kill -l $signal))) ]; then
        fail "SIG$signal while a timed run is running: exit $code: $(tail -1 "$work/err.txt")"
    fi
    survivors=$(pgrep -g $pid)
    if [ -n "$survivors" ]; then
        fail "SIG$signal while a timed run is running: process(es) $survivors of the bench" \
            "survive it (the timed run was $child)"
        kill -s KILL $survivors 2>/dev/null
    fi
    complete_files "$dir/out" "SIG$signal while a timed run is running"
    left=$(ls -A "$dir/tmp")
    [ -z "$left" ] && rmdir "$dir/tmp" || fail "SIG$signal: left in TMPDIR: $left"
    echo "SIG$signal while the timed run $child is running: exit $code," \
        "$(find "$dir/out" -type f | wc -l) file(s) written"
done

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "stopped while a timed run is running: the run stopped with rotbeam, nothing half-written"
