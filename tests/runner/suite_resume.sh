#!/usr/bin/env bash
# `rotbeam suite` is restartable and deterministic: a suite killed midway
# (SIGKILL, no chance to clean up) and rerun ends with the same results as an uninterrupted run,
# every result file is complete JSON at every moment (atomic writes), finished runs are not
# redone, and the results do not depend on --jobs. Usage: suite_resume.sh ROTBEAM
set -u
rotbeam=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cases='cantilever-moment*'

# Reference: one uninterrupted run on one thread.
"$rotbeam" suite --cases "$cases" --jobs 1 --out "$work/ref" >/dev/null 2>&1 || fail "reference suite failed"
total=$(ls "$work/ref/runs" | wc -l)
[ "$total" -ge 8 ] || fail "reference suite wrote $total runs"

# Interrupted: kill -9 as soon as a few results exist, check what is on disk, then resume.
"$rotbeam" suite --cases "$cases" --jobs 2 --out "$work/resumed" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    n=$(ls "$work/resumed/runs" 2>/dev/null | grep -c '\.json$')
    [ "$n" -ge 3 ] && break
    sleep 0.01
done
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
finished=$(ls "$work/resumed/runs" | grep -c '\.json$')
[ "$finished" -lt "$total" ] || echo "note: the suite finished before it was killed ($finished runs)"
for f in "$work"/resumed/runs/*.json; do
    python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$f" 2>/dev/null ||
        fail "damaged result after kill: $f"
done
before=$(stat -c '%n %Y.%y' "$work"/resumed/runs/*.json | sort)
"$rotbeam" suite --cases "$cases" --jobs 2 --out "$work/resumed" >/dev/null 2>&1 || fail "resumed suite failed"
# Finished runs were skipped: their files are untouched.
while read -r name stamp; do
    now=$(stat -c '%Y.%y' "$name")
    [ "$now" = "$stamp" ] || fail "finished run redone on resume: $name"
done <<<"$before"

# Same results as the reference, apart from timings (wall_seconds).
python3 - "$work/ref/runs" "$work/resumed/runs" <<'PY' || fail "resumed or --jobs 2 results differ from the reference"
import json, os, sys
ref, res = sys.argv[1], sys.argv[2]
def strip(j):
    j.pop("wall_seconds", None)
    return j
names = sorted(os.listdir(ref))
assert names == sorted(os.listdir(res)), (names, sorted(os.listdir(res)))
for n in names:
    a = strip(json.load(open(os.path.join(ref, n))))
    b = strip(json.load(open(os.path.join(res, n))))
    assert a == b, n
PY

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "suite resume: killed after $finished of $total runs, resumed, identical to the uninterrupted run"
