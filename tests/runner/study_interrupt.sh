#!/usr/bin/env bash
# Nothing half-written by `rotbeam study NAME` (docs/durability.md), for every study the registry
# lists (the names are read from rotbeam's own refusal of an unknown study, so a study added to
# distribution/study_registry.cpp is covered without editing this file):
# - stopped by SIGINT at its first file, then rerun into the same folder and stopped by SIGKILL
#   at its next new file, then by SIGTERM at the next: exit 128 + signal (one line saying so for
#   SIGINT/SIGTERM), only complete files left (complete_files: JSON that parses, text files that
#   end with their newline, CSV rows of the header's width, PNGs that end with IEND, SVGs with
#   their closing tag), no temporary (after SIGKILL: hidden temporaries at most);
# - then, in the same folder, under a file size limit of 1 KiB (ulimit -f, the EFBIG of a full
#   disk; the data files are smaller, the figures and the study's JSON larger): exit 4, the last
#   line of stderr names a file of the folder and the limit, only complete files left.
# Each rerun goes further than the stop before it (a stop waits for a file the folder did not
# hold yet, and the joined beam's studies keep their computed references), so each study is
# stopped at a few successive points for about the cost of one quick study. The studies run in
# their --quick form: a study's first files are of the same kinds as its last (data, Markdown,
# JSON, figures through gnuplot); the full forms differ by more points, not by other writes.
# Usage: study_interrupt.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work, fail and failures; complete_files and limited.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
# Background jobs in their own process group: a non-interactive shell would otherwise start
# them with SIGINT ignored, which rotbeam (rightly) leaves ignored.
set -m

studies=$("$rotbeam" study no-such-study 2>&1 | sed -n 's/.*(available: \(.*\), all)$/\1/p' |
    tr -d ',')
[ "$(wc -w <<<"$studies")" -ge 2 ] || fail "no study names in rotbeam's refusal: '$studies'"

# The arguments of study NAME writing into DIR.
study_args() {  # study_args NAME DIR
    if [ "$1" = rotations ]; then
        echo "study rotations --samples 721 --json $2/rotations.json"
    else
        echo "study $1 --quick --out $2"
    fi
}

# Files rotbeam has written into DIR (temporaries included: a write in flight counts).
files_in() { find "$1" -type f 2>/dev/null | wc -l; }

# stop NAME SIGNAL: the study, into its folder, stopped by SIGNAL once the folder holds a file
# more than before.
stop() {
    local name=$1 signal=$2 dir="$work/$1"
    mkdir -p "$dir"
    local start=$SECONDS n
    n=$(($(files_in "$dir") + 1))
    # shellcheck disable=SC2046 # the arguments are words without spaces
    "$rotbeam" $(study_args "$name" "$dir") >/dev/null 2>"$work/err.txt" &
    local pid=$!
    while [ "$(files_in "$dir")" -lt "$n" ] && kill -0 $pid 2>/dev/null; do sleep 0.02; done
    kill -s "$signal" $pid 2>/dev/null
    wait $pid 2>/dev/null
    local code=$?
    if [ $code -eq 0 ]; then
        echo "note: study $name finished before SIG$signal ($((SECONDS - start)) s)"
    elif [ $code -ne $((128 + $(kill -l "$signal"))) ]; then
        fail "study $name, SIG$signal: exit $code: $(tail -1 "$work/err.txt")"
    elif [ "$signal" != KILL ] && ! grep -q "stopped by SIG$signal" "$work/err.txt"; then
        fail "study $name, SIG$signal: no line saying so"
    fi
    if [ "$signal" = KILL ]; then
        complete_files "$dir" "study $name after SIG$signal" temporaries-allowed
        # What the next suite into the folder would clear (a study command does not): the later
        # stops must leave no temporary of their own.
        find "$dir" -name '.*.rotbeam-tmp.*' -delete
    else
        complete_files "$dir" "study $name after SIG$signal"
    fi
    echo "study $name: SIG$signal at file $n after $((SECONDS - start)) s, exit $code"
}

# full NAME KIB: the study, into its folder, under a file size limit of KIB KiB.
full() {
    local name=$1 kib=$2 dir="$work/$1"
    mkdir -p "$dir"
    local start=$SECONDS
    # shellcheck disable=SC2046
    limited "$kib" "$work/err.txt" "$rotbeam" $(study_args "$name" "$dir")
    local code=$?
    local last
    last=$(tail -1 "$work/err.txt")
    if [ $code -ne 4 ]; then
        fail "study $name, ulimit -f $kib: exit $code, expected 4: $last"
    elif ! grep -q "^rotbeam: $dir/.*: write failed, nothing written: file too large" <<<"$last"; then
        fail "study $name, ulimit -f $kib: the last line does not name the file: $last"
    fi
    complete_files "$dir" "study $name under ulimit -f $kib"
    echo "study $name: ulimit -f $kib, exit $code after $((SECONDS - start)) s:" \
        "${last#rotbeam: $dir/}"
}

for name in $studies; do
    stop "$name" INT
    stop "$name" KILL
    stop "$name" TERM
    full "$name" 1
done

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "every study ($(wc -w <<<"$studies")) stopped by SIGINT/SIGKILL/SIGTERM and by a file size" \
    "limit left only complete files"
