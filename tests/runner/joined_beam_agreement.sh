#!/usr/bin/env bash
# `rotbeam study joined-beam-agreement --quick` (issue 9 item 5): the joined beam under the dead
# joint force, 0–0.2 s; the mixed formulation on 10, 20, 40, 80 elements per member (IDA at 1e-7)
# against the displacement formulation with order-4 elements (time-extrapolated). Asserts what
# the full study's conclusion rests on: the agreement falls at the mixed element's order 2 (each
# halving of the elements divides it by more than 2^1.5), the Richardson extrapolations in space
# fall with refinement to the references' own uncertainty (within a factor 2), that uncertainty
# is below the finest mesh's distance, and the data files are written. A mixed response that
# converged to another answer (a different load application, mass, follower linearization) would
# stop falling and fail here. Usage: joined_beam_agreement.sh ROTBEAM
set -u
rotbeam=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$rotbeam" study joined-beam-agreement --quick --out "$work/s" >/dev/null 2>&1 ||
    fail "study failed"
python3 - "$work/s" <<'PY' || fail "agreement does not converge at order 2, or output missing"
import json, os, sys
d = sys.argv[1]
j = json.load(open(os.path.join(d, "study-joined-beam-agreement.json")))
case = j["cases"][0]
a = case["agreement"]
print("agreement", a, "orders", case["agreement_orders"], "extrapolated",
      case["extrapolated_agreement"], "time checks", j["time_checks"])
assert case["case"] == "joined-beam-dead" and case["elements_per_member"] == [10, 20, 40, 80]
assert all(x is not None for x in a), a
# Order 2 in space: every halving divides the distance by more than 2^1.5.
for coarse, fine in zip(a, a[1:]):
    assert coarse / fine > 2 ** 1.5, (coarse, fine)
# The Richardson extrapolations in space from successive pairs fall too (by more than 2 per
# halving), and the finest one reaches the references' own uncertainty: the two formulations have
# the same limit. The uncertainty: displacement order 3 against 4 (space), the displacement time
# extrapolation against one at half the steps, IDA at 1e-7 against 1e-8.
e = case["extrapolated_agreements"][1:]
for coarse, fine in zip(e, e[1:]):
    assert coarse / fine > 2, e
tc = j["time_checks"]
floor = (case["displacement_p3_vs_p4"] + tc["displacement_p3_pair_vs_half_pair"]
         + tc["mixed_ida_vs_tighter"])
assert e[-1] < 2 * floor, (e[-1], floor)
# ...and that uncertainty is below what is compared: the finest mesh's distance is resolved.
assert floor < a[-1], (floor, a[-1])
for f in ("agreement_joined-beam-dead_joint.csv", "agreement_joined-beam-dead_vs_elements.dat",
          "agreement_joined-beam-dead_du_mixed_40.dat"):
    assert os.path.getsize(os.path.join(d, "data", f)) > 0, f
md = open(os.path.join(d, "study-joined-beam-agreement.md")).read()
assert "Richardson in space" in md
PY
exit $((failures > 0))
