#!/usr/bin/env bash
# The kinematic check of the mixed formulation (core/kinematic_check.hpp): a run whose discrete
# kinematics no longer follow the elements' curvature ends with status kinematics-unresolved,
# naming the load step, the load factor, the element and the angles; runs whose elements resolve
# the rotation are not flagged. Usage: kinematic_check.sh ROTBEAM
#
# The flagged runs are the precessing helix on its catalog mesh (16 elements) with the
# three-parameter charts, which reach κL = 4π with status converged before the check and tips
# 0.42–0.49 L from the continuum reference (docs/mixed-formulation.md). The quaternion on the same
# mesh (0.13 L, the mesh's error: it falls at order 2) and the displacement formulation
# (3.5e-4 L) are not flagged, nor are the roll-up to λ = 4, the helix and the 45° bend.
set -u
rotbeam=$1
# work (a scratch folder), fail and failures.
. "$(dirname "$0")/scratch.sh"

status_of() {  # status_of NAME CASE ARGS...: runs, writes $work/NAME.json
    local name=$1
    shift
    "$rotbeam" run "$@" --quiet --json "$work/$name.json" || fail "$name: exit $?"
}

status_of rv helix-precessing --formulation mixed --rotation rotation-vector
status_of wm helix-precessing --formulation mixed --rotation wiener-milenkovic
status_of wmc helix-precessing --formulation mixed --rotation wiener-milenkovic \
    --set discretization.wm_map=continuous
status_of q helix-precessing --formulation mixed --rotation quaternion
status_of d helix-precessing
status_of rv32 helix-precessing --formulation mixed --rotation rotation-vector --elements 32
status_of roll-q cantilever-moment-4 --formulation mixed --rotation quaternion
status_of roll-rv cantilever-moment-4 --formulation mixed --rotation rotation-vector
status_of helix-rv helix --formulation mixed --rotation rotation-vector
status_of bend-wm bend-45 --formulation mixed --rotation wiener-milenkovic
"$rotbeam" reference helix-precessing --json "$work/ref.json" >/dev/null || fail "reference"
python3 - "$work" <<'PY' || fail "statuses"
import json, math, re, sys
# A solved state: the tolerances met, or the residual at its round-off floor with a bound
# (docs/solver-convergence.md).
SOLVED = ("converged", "stalled-at-round-off")
work = sys.argv[1]
load = lambda n: json.load(open(f"{work}/{n}.json"))
bad = 0
for n in ["rv", "wm", "wmc"]:
    r = load(n)
    m = r["message"]
    ok = (r["status"] == "kinematics-unresolved"
          and re.search(r"load step \d+ \(load factor [0-9.]+\): element \d+ of member 'beam' "
                        r"turns by [0-9.e-]+ rad", m) is not None
          and "not trustworthy" in m)
    print(f"{n}: {r['status']}: {m[:160]}", "" if ok else "  <-- FAIL")
    bad += not ok
    # The steps before the flagged one are reported; the flagged one and later ones are not.
    bad += len(r["steps"]) >= 4
ref = load("ref")["steps"]
for n in ["q", "d", "rv32", "roll-q", "roll-rv", "helix-rv", "bend-wm"]:
    r = load(n)
    ok = r["status"] in SOLVED
    print(f"{n}: {r['status']}", "" if ok else f"  <-- FAIL: {r['message'][:200]}")
    bad += not ok
# For the record (printed, not asserted): the unflagged precessing-helix runs' tip error at κL = 4π
# (quaternion 16 elements 0.13 L, rotation vector 32 elements 0.046 L: order-2 mesh error).
for n in ["q", "rv32", "d"]:
    tip = load(n)["steps"][-1]["points"]["tip"]["displacement"]
    e = math.dist(tip, ref[-1]["points"]["tip"]["displacement"]) / 10.0
    print(f"{n}: tip error at 4π {e:.3e} L")
sys.exit(1 if bad else 0)
PY

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "kinematic check: all checks passed"
