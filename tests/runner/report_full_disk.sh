#!/usr/bin/env bash
# The suite's summaries on a full disk (docs/durability.md). A copy of the quick suite (the ctest
# fixture quick_suite) is resumed under file size limits (ulimit -f, the EFBIG of a full disk):
# every run is found written and skipped, so only what the suite writes after its runs is written
# again (published.md, rotation-study.json, then the report), a few seconds each. Each limit stops
# the suite at another file; each must exit 4 with its last line naming a file of the folder and
# the limit, leave only complete files (complete_files), and a resume without the limit must give
# the fixture's results again.
# Usage: report_full_disk.sh ROTBEAM COMPARE_RESULTS_PY QUICK_SUITE
set -u
suite=$3
# rotbeam, compare; work, fail and failures; same, complete_files and limited.
. "$(dirname "$0")/results_check.sh" "$1" "$2"

[ -f "$suite/index.md" ] || fail "no quick suite in $suite (the fixture quick_suite failed?)"
# The limits in KiB: 1 stops at the first file written (published.md, 32 KiB), 48 at the rotation
# study (rotation-study.json, 1.4 MiB). The report's figures (at most 170 KiB) and pages come after
# the rotation study and are smaller, so no limit reaches them here; the studies' figures, written
# before anything larger, are test_study_interrupt's.
stopped=""
for kib in 1 48; do
    dir="$work/full-$kib"
    cp -r "$suite" "$dir"
    limited "$kib" "$work/err.txt" "$rotbeam" suite --quick --no-studies --jobs 2 --out "$dir"
    code=$?
    last=$(tail -1 "$work/err.txt")
    if [ $code -eq 4 ]; then
        grep -q "^rotbeam: $dir/.*: write failed, nothing written: file too large" <<<"$last" ||
            fail "ulimit -f $kib: the last line does not name the file and the limit: $last"
        name=${last#rotbeam: "$dir"/}
        stopped="$stopped ${name%%: write failed*}"
    else
        fail "ulimit -f $kib: exit $code, expected 4: $last"
    fi
    complete_files "$dir" "the suite under ulimit -f $kib"
    echo "ulimit -f $kib: exit $code: ${last#rotbeam: $dir/}"
    "$rotbeam" suite --quick --no-studies --jobs 2 --out "$dir" >/dev/null 2>"$work/err.txt" ||
        fail "resume after ulimit -f $kib failed: $(tail -1 "$work/err.txt")"
    complete_files "$dir" "resumed after ulimit -f $kib"
    same "$suite" "$dir" "the suite resumed after ulimit -f $kib"
    rm -rf "$dir"
done
# Both limits must stop the suite, at two different files.
[ "$(tr ' ' '\n' <<<"$stopped" | sort -u | grep -c .)" -eq 2 ] || fail "stopped at:$stopped"

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "summaries on a full disk: each limit stopped with exit 4 naming its file, nothing cut short," \
    "resumed to the same results"
