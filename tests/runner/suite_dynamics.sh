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

# --estimate off: this test checks the planning and the dynamic statuses, not the estimates (unit
# and verification tests do: test_estimates, test_estimate_dynamic); with them the 20 dynamic runs'
# companions cost 4x (displacement: p+1, dt/2) to 8x (mixed: h/2, h/4, dt/2) the runs, minutes of
# the CI budget (docs/error-estimates.md, Cost). The quick suite below is estimated.
"$rotbeam" suite --cases 'joined-beam*' --no-studies --jobs 2 --estimate off --out "$work/s" \
    >/dev/null 2>&1 || fail "suite failed"
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
# The suite estimates by default: every solved run carries its estimate, and the summary holds each
# against the case's stated accuracy (no combination is left "unchecked"); --estimate off says so.
python3 - "$work/q" "$work/s" <<'PY' || fail "the suite's estimates are missing or not used"
import json, os, sys
for d, want in ((sys.argv[1], "on"), (sys.argv[2], "off")):
    for n in os.listdir(os.path.join(d, "runs")):
        j = json.load(open(os.path.join(d, "runs", n)))
        e = j["estimate"]["status"]
        if want == "off":
            assert e == "off", (n, e)
        elif j["status"] in ("converged", "stalled-at-round-off"):
            assert e == "estimated", (n, e)
        else:
            assert e == "not-estimated", (n, j["status"], e)
md = open(os.path.join(sys.argv[1], "index.md")).read()
assert "met (estimate)" in md and "[unchecked]" not in md
PY

if [ $failures -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "suite dynamics: ok"
