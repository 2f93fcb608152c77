#!/usr/bin/env bash
# `rotbeam suite` plans the dynamic and modal catalog cases: every formulation ×
# parameterization of the joined beam's dead and follower runs with a time history where
# available and a recorded refusal otherwise, Table III's variants (the published columns'
# settings, the refined mesh), the report's Table III and Figs. 6–7 sections with their data and,
# when gnuplot is installed, the figure; --quick plans no dynamic run. Usage: suite_dynamics.sh ROTBEAM
set -u
rotbeam=$1
# work (a scratch folder), fail and failures.
. "$(dirname "$0")/scratch.sh"

"$rotbeam" suite --cases 'joined-beam*' --no-studies --jobs 2 --out "$work/s" >/dev/null 2>&1 ||
    fail "suite failed"
python3 - "$work/s" <<'PY' || fail "dynamic or modal runs missing or malformed"
import json, os, sys
runs = os.path.join(sys.argv[1], "runs")
names = os.listdir(runs)
for case in ("joined-beam-dead", "joined-beam-follower"):
    mine = [n for n in names if n.startswith(case + "_")]
    assert len(mine) == 10, (case, mine)  # 2 formulations × 5 parameterizations
    # Every combination has the dynamic analysis: each run must reach t = 2 s with a solution.
    # The displacement runs' time steps meet the case's 1e-12 residual tolerance or stall at
    # their round-off floor (docs/solver-convergence.md), which the message must quantify.
    for n in mine:
        j = json.load(open(os.path.join(runs, n)))
        assert j["status"] in ("converged", "stalled-at-round-off"), (n, j["status"], j["message"])
        if j["status"] == "stalled-at-round-off":
            assert "expected floor" in j["message"], (n, j["message"])
        assert "time" in j["steps"][-1] and abs(j["steps"][-1]["time"] - 2.0) < 1e-6, n
    wm = json.load(open(os.path.join(runs, case + "_wiener-milenkovic_mixed.json")))
    assert wm["status"] == "converged", wm["message"]
assert any(n.startswith("joined-beam-160-per-member_") for n in names), names
assert any(n.startswith("joined-beam-as-published-") and n.endswith("_displacement.json")
           for n in names), names
PY
md="$work/s/index.md"
for section in "## Table III" "## Figs. 6–7"; do
    grep -q "^$section" "$md" || fail "report lacks '$section'"
done
ls "$work"/s/data/joined_dead_*.dat >/dev/null 2>&1 || fail "no joint history data files"
if command -v gnuplot >/dev/null; then
    [ -s "$work/s/joined-beam-joint.png" ] || fail "joined-beam-joint.png not drawn"
fi

"$rotbeam" suite --quick --no-studies --out "$work/q" >/dev/null 2>&1 || fail "quick suite failed"
if ls "$work/q/runs" | grep -q -e joined-beam -e blade; then fail "--quick planned dynamic runs"; fi

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "suite dynamics: ok"
