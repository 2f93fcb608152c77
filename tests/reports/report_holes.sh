#!/usr/bin/env bash
# check_report.py can fail: two small real reports (`rotbeam suite --quick --cases bend-45
# --no-studies --estimate off`, its ten runs, the rotation study and its figure, ~3 CPU-s; and the
# example sweep cases/sweeps/rollup-load-elements.yaml, 24 runs and sweep.csv, ~1 CPU-s) pass it
# as written, and a copy of one with one hole injected fails it, with a line naming the hole:
# a linked image removed, a malformed number in a table, NaN in a run's steps, a negative time,
# an element order that is not the run's own (inside the format's 1…24, outside the run's
# mesh), NaN in a figure's data file and inf in a CSV.
# Usage: report_holes.sh ROTBEAM SOURCE_DIR
set -u
rotbeam=$1
src=$2
check=$src/tests/reports/check_report.py
. "$src/tests/runner/scratch.sh"

"$rotbeam" suite --quick --cases bend-45 --no-studies --estimate off --jobs 2 \
    --out "$work/suite" >/dev/null 2>"$work/err.txt" || fail "the small suite failed: $(tail -1 "$work/err.txt")"
"$rotbeam" sweep "$src/cases/sweeps/rollup-load-elements.yaml" --jobs 2 --out "$work/sweep" \
    >/dev/null 2>"$work/err.txt" || fail "the sweep failed: $(tail -1 "$work/err.txt")"
for r in suite sweep; do
    python3 "$check" "$work/$r" >"$work/out.txt" || fail "the real $r report fails: $(head -3 "$work/out.txt")"
done

# hole NAME REPORT EXPECTED PYTHON: a copy of REPORT changed by PYTHON (run in the copy) must
# make the checker exit 1 with a line holding EXPECTED.
hole() {
    local name=$1 report=$2 expected=$3 edit=$4 copy="$work/hole"
    rm -rf "$copy" && cp -r "$work/$report" "$copy"
    (cd "$copy" && python3 -c "$edit") || { fail "$name: the edit failed"; return; }
    python3 "$check" "$copy" >"$work/out.txt"
    local code=$?
    if [ $code -ne 1 ]; then
        fail "$name: the checker exited $code, expected 1"
    elif ! grep -qF -- "$expected" "$work/out.txt"; then
        fail "$name: no line with '$expected': $(head -3 "$work/out.txt")"
    else
        echo "$name: $(grep -F -- "$expected" "$work/out.txt" | head -1)"
    fi
}
run=runs/bend-45_quaternion_displacement.json
hole "a linked image missing" suite "links rotation-study.png, which does not exist" \
    'import os; os.remove("rotation-study.png")'
# The first number in scientific notation in a table row of index.md gets a second decimal point.
hole "a malformed table number" suite "malformed number '1.2.3e-05'" '
import re
lines = open("index.md").read().split("\n")
i = next(i for i, l in enumerate(lines) if l.startswith("|") and re.search(r"\d\.\d+e-\d+", l))
lines[i] = re.sub(r"\d\.\d+e-\d+", "1.2.3e-05", lines[i], count=1)
open("index.md", "w").write("\n".join(lines))'
hole "NaN in a run's steps" suite "$run.steps[0].load_factor: nan (NaN or infinite)" "
import json
j = json.load(open('$run'))
j['steps'][0]['load_factor'] = float('nan')
json.dump(j, open('$run', 'w'))"
hole "a negative time" suite "$run.wall_seconds: negative time -1.5" "
import json
j = json.load(open('$run'))
j['wall_seconds'] = -1.5
json.dump(j, open('$run', 'w'))"
# bend-45's catalog mesh is 16 elements of order 3: 49 nodes. Order 5 is a valid order, not its.
hole "an order outside the run's own" suite "$run: element order 5 outside the run's own" "
import json
j = json.load(open('$run'))
j['order'] = 5
json.dump(j, open('$run', 'w'))"
# The second field of the first data row (line 2, below the column names).
hole "NaN in a data file" suite "data/rotation-study.dat:2: 'nan' (NaN or infinite)" '
lines = open("data/rotation-study.dat").read().split("\n")
i = next(i for i, l in enumerate(lines) if l.split() and l.split()[0][0].isdigit())
fields = lines[i].split()
fields[1] = "nan"
lines[i] = " ".join(fields)
open("data/rotation-study.dat", "w").write("\n".join(lines))'
hole "inf in a CSV" sweep "sweep.csv:3: 'inf' (NaN or infinite) in a data file" '
import csv
rows = list(csv.reader(open("sweep.csv", newline="")))
rows[2][rows[0].index("u1")] = "inf"
csv.writer(open("sweep.csv", "w", newline=""), lineterminator="\n").writerows(rows)'

[ $failures -eq 0 ] && echo "report holes: every hole fails the checker, naming it"
exit $((failures > 0))
