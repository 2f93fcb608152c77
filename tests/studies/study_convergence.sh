#!/usr/bin/env bash
# The convergence study's report names the element orders it ran: the p-refinement orders in the
# header of study-convergence.md are those of the runs, read back from the unknowns each run had
# (2 clamped elements of order p: 2p free nodes of 6 unknowns, 12p). Runs the study path itself
# (`rotbeam study convergence --quick`, ~4 s), so that a header built from a dangling reference
# prints garbage here and under the sanitizers. Usage: study_convergence.sh ROTBEAM
set -u
rotbeam=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$rotbeam" study convergence --quick --out "$work" >"$work/log" 2>&1 ||
    { echo "FAIL: study convergence exited $?: $(cat "$work/log")"; exit 1; }
python3 - "$work" <<'PY'
import json, re, sys
work = sys.argv[1]
md = open(f"{work}/study-convergence.md").read()
m = re.search(r"\(2 elements, orders ([^)]*)\)", md)
if not m:
    sys.exit("FAIL: the header names no p-refinement orders")
printed = [int(p) for p in m.group(1).split(", ")]
study = json.load(open(f"{work}/study-convergence.json"))
failures = 0
series = [s for c in study["cases"] for s in c["series"] if s["label"].endswith("/p")]
if not series:
    sys.exit("FAIL: no p-refinement series in study-convergence.json")
for s in series:
    ran = [round(d / 12) for d in s["dofs"]]
    if ran != printed:
        print(f"FAIL: {s['label']}: runs had orders {ran}, the header prints {printed}")
        failures += 1
# The quick p-refinement: orders 2, 4, 6, 8 (studies/study_convergence.cpp, refinements).
if printed != [2, 4, 6, 8]:
    print(f"FAIL: header orders {printed}, the quick study runs 2, 4, 6, 8")
    failures += 1
print(f"{len(series)} p-refinement series, orders {printed}: " + ("ok" if not failures else "FAILED"))
sys.exit(1 if failures else 0)
PY
