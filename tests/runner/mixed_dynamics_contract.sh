#!/usr/bin/env bash
# The runner's mixed dynamic and modal analyses (runs/run_mixed_dynamics.cpp):
# a short joined-beam response per parameterization and integrator writes its JSON and CSV history
# with the joint's columns (the quaternion also its norm drift), IDA's tolerances are taken from
# the case, a damped case runs, a damped modal analysis and an unknown integrator are refused as
# bad input (the displacement formulation's damped modal analysis says it leaves the damping out),
# and the joined beam's modes are reported with growth rates (the quaternion's equal to
# WM's).
# Usage: mixed_dynamics_contract.sh ROTBEAM SOURCE_DIR
set -u
rotbeam=$1
src=$2
# work (a scratch folder), fail and failures.
. "$(dirname "$0")/scratch.sh"

# The error estimate (on by default) for Wiener-Milenkovic, the mixed formulation's default, with
# each integrator; off for the other parameterizations, whose contract here (history, JSON, dofs)
# does not involve it: a mixed dynamic run's estimate makes 8 companion runs (h/2, h/4, dt/2;
# docs/error-estimates.md, Cost), ~9x the run (1.8 against 0.2 CPU-s in Release), and under the
# sanitizers the 15 estimated runs were most of this test's time (docs/quality-checks.md, Time).
for rotation in wiener-milenkovic rodrigues rotation-vector euler-angles quaternion; do
    estimate=off
    [ $rotation = wiener-milenkovic ] && estimate=on
    for integrator in trapezoidal ida radau-iia-3; do
        out="$work/$rotation-$integrator"
        "$rotbeam" run "$src/cases/joined-beam-follower.yaml" --formulation mixed --rotation "$rotation" \
            --set analysis.integrator=$integrator --set analysis.end_time=0.05 \
            --set analysis.output_interval=0.01 --estimate $estimate --out "$out" --json "$out.json" \
            >/dev/null 2>&1
        rc=$?
        [ $rc -eq 0 ] || fail "$rotation/$integrator: exit $rc"
        csv=$(ls "$out"/*.csv 2>/dev/null | head -1)
        [ -n "$csv" ] || { fail "$rotation/$integrator: no CSV history"; continue; }
        head -1 "$csv" | grep -q "joint_uz" || fail "$rotation/$integrator: CSV header lacks joint_uz"
        # One row per output time 0, 0.01, …, 0.05 plus the header.
        [ "$(wc -l <"$csv")" -eq 7 ] || fail "$rotation/$integrator: $(wc -l <"$csv") CSV lines, expected 7"
        python3 - "$out.json" "$integrator" "$rotation" "$estimate" <<'PY' ||
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "converged", r["message"]
assert r["dynamics"]["integrator"] == sys.argv[2]
assert r["estimate"]["status"] == ("estimated" if sys.argv[4] == "on" else "off"), r["estimate"]
# 18 per element and 6 per node; the quaternion 19 per element, 7 per free node, 6 + 7 (ρ) at the
# two clamped roots.
if sys.argv[3] == "quaternion":
    assert r["dofs"] == 19 * 20 + 7 * 19 + 6 + 7, r["dofs"]
    assert r["quaternion_norm_drift"]["nodes"] < 1e-8, r["quaternion_norm_drift"]
else:
    assert r["dofs"] == 486
steps = r["steps"]
assert abs(steps[-1]["time"] - 0.05) < 1e-12, steps[-1]["time"]
# The follower force 1e5 sin(20 t) pushes the joint up: u_z > 0 at t = 0.05 s.
assert steps[-1]["points"]["joint"]["displacement"][2] > 0.0
assert "reaction_force" in steps[-1]["points"]["root1"]
PY
            fail "$rotation/$integrator: JSON contract"
    done
done

# IDA's tolerances from the case (analysis.relative_tolerance, absolute_tolerance): looser
# tolerances take fewer steps than the default 1e-6.
"$rotbeam" run "$src/cases/joined-beam-follower.yaml" --formulation mixed --rotation rodrigues \
    --set analysis.integrator=ida --set analysis.end_time=0.05 --set analysis.relative_tolerance=1e-4 \
    --set analysis.absolute_tolerance=1e-4 --estimate off --json "$work/tol.json" >/dev/null 2>&1 ||
    fail "IDA with case tolerances: exit $?"
python3 - "$work/tol.json" "$work/rodrigues-ida.json" <<'PY' || fail "IDA tolerances from the case"
import json, sys
loose, default = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert loose["dynamics"]["relative_tolerance"] == 1e-4 and loose["dynamics"]["absolute_tolerance"] == 1e-4
assert default["dynamics"]["relative_tolerance"] == 1e-6
assert loose["dynamics"]["steps"] < default["dynamics"]["steps"], (loose["dynamics"]["steps"], default["dynamics"]["steps"])
PY

# Bad input: an unknown integrator, and damping in a modal analysis (its modes are undamped).
"$rotbeam" run "$src/cases/joined-beam-dead.yaml" --formulation mixed --rotation rodrigues \
    --set analysis.integrator=rk4 >"$work/out" 2>"$work/err"
[ $? -eq 2 ] || fail "unknown integrator not refused with exit 2"
grep -q "trapezoidal | ida" "$work/err" || fail "unknown integrator message: $(cat "$work/err")"
sed -E 's/^(    density: 2700)$/\1\n    damping: [0, 0, 0, 1.0e-4, 1.0e-4, 1.0e-4]/' \
    "$src/cases/joined-beam.yaml" >"$work/damped-modal.yaml"
grep -q "damping:" "$work/damped-modal.yaml" || fail "could not make the damped modal case"
"$rotbeam" run "$work/damped-modal.yaml" --formulation mixed --rotation rodrigues --json "$work/d.json" \
    >"$work/out" 2>"$work/err"
[ $? -eq 2 ] || fail "damped modal analysis not refused with exit 2: $(cat "$work/err")"
grep -q "damping is not available in the mixed modal analysis" "$work/err" ||
    fail "damping message: $(cat "$work/err")"
[ ! -e "$work/d.json" ] || fail "a result file was written for a refused damped modal case"
# The displacement formulation's modes of the same case are the undamped structure's: it runs, and
# its message and JSON say that the damping is left out (not dropped unsaid).
"$rotbeam" run "$work/damped-modal.yaml" --formulation displacement --estimate off \
    --json "$work/dd.json" >"$work/out" 2>"$work/err" ||
    fail "damped modal analysis, displacement formulation: exit $?: $(cat "$work/err")"
grep -q "the sections' damping is left out (undamped modes)" "$work/out" ||
    fail "damped modal, displacement: the output does not say the damping is left out"
python3 - "$work/dd.json" <<'PY' || fail "damped modal, displacement: JSON"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["modal"]["damping"].startswith("left out"), r["modal"]
assert "damping is left out" in r["message"], r["message"]
PY
# The dynamics carry the damping (formulations/mixed/mixed_damping.hpp).
sed -E 's/^(    density: 2700)$/\1\n    damping: [0, 0, 0, 1.0e-4, 1.0e-4, 1.0e-4]/' \
    "$src/cases/joined-beam-follower.yaml" >"$work/damped.yaml"
grep -q "damping:" "$work/damped.yaml" || fail "could not make the damped case"
"$rotbeam" run "$work/damped.yaml" --formulation mixed --rotation rodrigues \
    --set analysis.end_time=0.05 --estimate off --json "$work/damped.json" >"$work/out" 2>"$work/err" ||
    fail "damped dynamics: exit $?: $(cat "$work/err")"
python3 - "$work/damped.json" <<'PY' || fail "damped dynamics JSON"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "converged", r["message"]
assert r["counters"]["damping_terms"] > 0, r["counters"]
PY

# Modal: Table III's mesh, five modes with their growth rates (undamped: round-off).
"$rotbeam" run "$src/cases/joined-beam.yaml" --json "$work/modal.json" >/dev/null 2>&1
python3 - "$work/modal.json" <<'PY' || fail "modal JSON contract"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "converged", r["message"]
f = r["frequencies_hz"]
assert len(f) == 5 and f == sorted(f), f
assert all(abs(m["growth_rate"]) < 1e-6 * 2 * 3.14159 * m["frequency_hz"] for m in r["modes"])
assert abs(r["modes"][0]["points"]["joint"]["displacement"][2]) > 0.1  # mode 1: out of plane
PY
"$rotbeam" run "$src/cases/joined-beam.yaml" --rotation quaternion --json "$work/modal-q.json" >/dev/null 2>&1
python3 - "$work/modal.json" "$work/modal-q.json" <<'PY' || fail "quaternion modal JSON"
import json, sys
wm, q = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert q["status"] == "converged", q["message"]
assert all(abs(a - b) < 1e-8 * a for a, b in zip(wm["frequencies_hz"], q["frequencies_hz"]))
assert abs(q["modes"][0]["points"]["joint"]["displacement"][2]) > 0.1
PY

if [ $failures -eq 0 ]; then echo "mixed dynamics contract: all checks passed"; exit 0; fi
echo "mixed dynamics contract: $failures failures"
exit 1
