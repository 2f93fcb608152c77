#!/usr/bin/env bash
# The reported rotation_angle is the norm of the rotation vector continued along the beam from the
# root (core/beam_rotation.hpp, docs/case-format.md §Results), so it does not depend on the load
# path. Usage: rotation_angle.sh ROTBEAM
#
# Tolerance: the continued angle of a state can be no more accurate than the state's rotation.
# Against an exact rotation R_exact with angle θ_exact (roll-up: λπ about −y; helix: κL about n),
# a run passes when |angle − θ_exact| ≤ angle(R_runᵀ R_exact) + 1e-9: to first order the norm of a
# rotation vector changes by the component of the rotation change along it (dexp⁻¹ ψ = ψ), so the
# continuation adds nothing to the mesh error of R itself; 1e-9 rad covers the Newton tolerance.
# Against the continuum reference of the precessing helix the same bound with a factor 1.5 for
# the second-order terms of a varying axis.
set -u
rotbeam=$1
# work (a scratch folder), fail and failures.
. "$(dirname "$0")/scratch.sh"

run() {  # run NAME CASE ARGS...: writes $work/NAME.json
    local name=$1
    shift
    "$rotbeam" run "$@" --quiet --json "$work/$name.json" || fail "$name: exit $?"
}

# Roll-up to λ = 2 and 4 in one load step, and along the catalog's load steps.
for rot in quaternion rotation-vector; do
    run "one2-$rot" cantilever-moment --rotation $rot --set 'analysis.load_factors=[2.0]' \
        --set analysis.substeps=1
    run "one4-$rot" cantilever-moment-4 --rotation $rot --set 'analysis.load_factors=[4.0]' \
        --set analysis.substeps=1
    run "many2-$rot" cantilever-moment --rotation $rot
    run "many4-$rot" cantilever-moment-4 --rotation $rot
done
run "one4-mixed" cantilever-moment-4 --formulation mixed --rotation quaternion \
    --set 'analysis.load_factors=[4.0]' --set analysis.substeps=1
run "many4-mixed" cantilever-moment-4 --formulation mixed --rotation quaternion

# Helix (fixed axis n, exact) and precessing helix (axis varying along the beam; the continuum
# reference continued along its R(s) at 401 sections).
run helix helix
run precessing helix-precessing
"$rotbeam" reference helix-precessing --json "$work/ref.json" >/dev/null || fail "reference: exit $?"
python3 - "$work" <<'PY' || fail "rotation angles"
import json, math, sys
# A solved state: the tolerances met, or the residual at its round-off floor with a bound
# (docs/solver-convergence.md).
SOLVED = ("converged", "stalled-at-round-off")
work = sys.argv[1]

def mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]

def tr(A):
    return [list(r) for r in zip(*A)]

def exp(psi):
    t = math.sqrt(sum(x * x for x in psi))
    k = [x / t for x in psi]
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    KK = mul(K, K)
    return [[(i == j) + math.sin(t) * K[i][j] + (1 - math.cos(t)) * KK[i][j] for j in range(3)]
            for i in range(3)]

def angle(R):  # rotation angle in [0, π]
    v = [R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]]
    return math.atan2(math.sqrt(sum(x * x for x in v)) / 2, (R[0][0] + R[1][1] + R[2][2] - 1) / 2)

def load(name):
    r = json.load(open(f"{work}/{name}.json"))
    assert r["status"] in SOLVED, (name, r["status"], r["message"])
    return r

def tip(name, lam):
    r = load(name)
    return [s for s in r["steps"] if abs(s["load_factor"] - lam) < 1e-12][-1]["points"]["tip"]

bad = 0
def check(what, value, exact, R_run, R_exact, factor=1.0):
    global bad
    mesh = angle(mul(tr(R_run), R_exact))
    ok = abs(value - exact) <= factor * mesh + 1e-9
    print(f"{what}: angle {value:.12f}, exact {exact:.12f}, rotation error {mesh:.3e}",
          "" if ok else "  <-- FAIL")
    bad += not ok

for name, lam in [("one2-quaternion", 2), ("one4-quaternion", 4), ("many2-quaternion", 2),
                  ("many4-quaternion", 4), ("one2-rotation-vector", 2),
                  ("one4-rotation-vector", 4), ("many2-rotation-vector", 2),
                  ("many4-rotation-vector", 4), ("one4-mixed", 4), ("many4-mixed", 4)]:
    p = tip(name, lam)
    check(name, p["rotation_angle"], lam * math.pi, p["rotation_matrix"], exp([0, -lam * math.pi, 0]))
# One step and many steps reach the same state: the same angle to the Newton tolerance.
for a, b, lam in [("one2-quaternion", "many2-quaternion", 2), ("one4-quaternion", "many4-quaternion", 4),
                  ("one4-rotation-vector", "many4-rotation-vector", 4), ("one4-mixed", "many4-mixed", 4)]:
    d = abs(tip(a, lam)["rotation_angle"] - tip(b, lam)["rotation_angle"])
    print(f"{a} vs {b}: {d:.2e}")
    bad += d > 1e-9
# The run's message names the continued largest rotation (the tip's 4π), not a principal π.
m = load("one4-quaternion")["message"]
if "largest nodal rotation 12.56" not in m:
    print("message of one4-quaternion:", m, "  <-- FAIL")
    bad += 1
for s in load("helix")["steps"]:
    kl, p = s["load_factor"], s["points"]["tip"]
    check(f"helix κL {kl:.6f}", p["rotation_angle"], kl, p["rotation_matrix"],
          exp([0.6 * kl, 0.0, 0.8 * kl]))
for s, sr in zip(load("precessing")["steps"], load("ref")["steps"]):
    p, q = s["points"]["tip"], sr["points"]["tip"]
    check(f"precessing κL {s['load_factor']:.6f}", p["rotation_angle"], q["rotation_angle"],
          p["rotation_matrix"], q["rotation_matrix"], 1.5)
sys.exit(1 if bad else 0)
PY

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "rotation_angle: all checks passed"
