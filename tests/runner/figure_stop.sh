#!/usr/bin/env bash
# A study stopped while gnuplot draws one of its figures (docs/durability.md): gnuplot is killed
# and waited for with rotbeam, so no figure or temporary of a figure appears after rotbeam has
# exited. SIGTERM and SIGHUP sent to rotbeam alone never reached gnuplot, which kept drawing and
# left a figure's hidden temporary; SIGINT was ignored while gnuplot ran (the C library's system()).
# Each stop waits for gnuplot's error file (rotbeam-gnuplot-PID-*.err in TMPDIR, created as gnuplot
# starts), signals rotbeam, then waits until no process names the folder any more before looking.
# Usage: figure_stop.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work, fail and failures; complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
# Background jobs in their own process group: SIGINT would otherwise be ignored (set by the shell).
set -m

for signal in TERM INT HUP; do
    dir="$work/$signal"
    mkdir -p "$dir/tmp"
    TMPDIR="$dir/tmp" "$rotbeam" study joined-beam-modal --quick --out "$dir/out" \
        >/dev/null 2>"$work/err.txt" &
    pid=$!
    while ! compgen -G "$dir/tmp/rotbeam-gnuplot-$pid-*.err" >/dev/null &&
        kill -0 $pid 2>/dev/null; do
        sleep 0.01
    done
    kill -s $signal $pid 2>/dev/null
    wait $pid
    code=$?
    # A gnuplot left running (its arguments name the folder) may still write; wait for it.
    for _ in $(seq 600); do
        pgrep -f -- "$dir/out/" >/dev/null || break
        sleep 0.1
    done
    if [ $code -ne $((128 + $(kill -l $signal))) ]; then
        fail "SIG$signal while gnuplot draws: exit $code: $(tail -1 "$work/err.txt")"
    fi
    if pgrep -f -- "$dir/out/" >/dev/null; then
        fail "SIG$signal while gnuplot draws: gnuplot still runs a minute after rotbeam stopped"
        pkill -KILL -f -- "$dir/out/"
    fi
    find "$dir/out" -name "*.rotbeam-tmp.*"  # named, if any, before the failure below
    complete_files "$dir/out" "SIG$signal while gnuplot draws"
    echo "SIG$signal while gnuplot draws: exit $code," \
        "$(find "$dir/out" -name '*.png' | wc -l) figure(s) kept"
done

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "stopped while gnuplot draws: gnuplot stopped with rotbeam, nothing half-written"
