#!/usr/bin/env bash
# `run --vtk`: the ParaView files of a static, a short dynamic and a modal run in both formulations
# and of a run with a turning root (the rotating-cantilever BeamDyn deck) in both, read back by
# meshio (vtk_check.py) and checked against the runs' JSON.
# Usage: vtk_output.sh ROTBEAM SOURCE_DIR PYTHON (a Python with Debian's python3-meshio)
set -u
rotbeam=$1
src=$2
python=$3
. "$(dirname "$0")/scratch.sh"

# check NAME CASE ARGS...: run with --vtk and --json into $work/NAME, then vtk_check.py. CASE is a
# catalog name or a case file.
check() {
    local name=$1 case=$2 file=$2
    shift 2
    [[ $case == *.yaml ]] || file="$src/cases/$case.yaml"
    "$rotbeam" run "$case" --quiet --vtk "$work/$name" --json "$work/$name/r.json" "$@" ||
        fail "$name: rotbeam run exit $?"
    "$python" "$(dirname "$0")/vtk_check.py" "$work/$name"/*.pvd "$work/$name/r.json" \
        "$file" || fail "$name: vtk_check.py"
}

check static-displacement cantilever-moment
check static-mixed cantilever-moment --formulation mixed --rotation rotation-vector
grep -q 'Name="section_moment"' "$work/static-mixed"/*_0006.vtu ||
    fail "static-mixed: no section_moment cell data"
grep -q 'Name="estimate_tip_displacement"' "$work/static-displacement"/*_0006.vtu ||
    fail "static-displacement: no estimate field data"
check dynamic free-vibration --estimate off --set analysis.end_time=0.02
# The mixed runs beside a displacement run of the same linear discrete model (linear elements,
# one-point stiffness and mass: the mixed element, docs/displacement-modal.md), compared at their
# shared nodes (vtk_compare.py) in every file.
linear=(--formulation displacement --order 1 --set discretization.mass_rule=midpoint
    --set discretization.quadrature=reduced)
check dynamic-linear free-vibration "${linear[@]}" --estimate off --set analysis.end_time=0.02
check dynamic-mixed free-vibration --formulation mixed --rotation rotation-vector --estimate off \
    --set analysis.end_time=0.02 --set analysis.integrator=trapezoidal \
    --set discretization.mass_rule=midpoint
grep -q 'Name="section_force"' "$work/dynamic-mixed"/*_0001.vtu ||
    fail "dynamic-mixed: no section_force cell data"
check modal joined-beam --formulation displacement --estimate off
check modal-mixed joined-beam --formulation mixed --estimate off
# A root turning at 1 rad/s about x: the inertial motion, the relative one as point data. The deck
# imported as a case file; its damping (which the mixed dynamics refuses) left out for the runs
# compared, 8 elements and no numerical dissipation (ρ∞ = 1, the trapezoidal rule's).
"$rotbeam" import beamdyn "$src/tests/data/beamdyn/rotating-cantilever/bd_driver.inp" \
    --out "$work/turning.yaml" >/dev/null || fail "import of the turning deck"
check turning-displacement "$work/turning.yaml" --estimate off
grep -v '^ *damping:' "$work/turning.yaml" >"$work/turning-undamped.yaml"
same=(--elements 8 --set analysis.rho_infinity=1 --estimate off)
check turning-linear "$work/turning-undamped.yaml" "${linear[@]}" "${same[@]}"
check turning-mixed "$work/turning-undamped.yaml" --formulation mixed "${same[@]}" \
    --set discretization.mass_rule=midpoint
# The modes (quaternion) about the deck's static state in the turning frame, at t = 0: the files'
# geometry is the JSON's static step.
"$python" -c 'import sys
s = open(sys.argv[1]).read()
open(sys.argv[2], "w").write(s[:s.index("analysis:")] + "analysis:\n  type: modal\n  modes: 4\n"
    "  about_static_state: true\n" + s[s.index("discretization:"):])' \
    "$work/turning-undamped.yaml" "$work/turning-modal.yaml" || fail "turning modal case"
check turning-modal-mixed "$work/turning-modal.yaml" --formulation mixed --elements 8 --estimate off
# compare A B TOLERANCE: the largest difference relative to the motion (or of the unit-normalized
# mode shapes, or of a rotation matrix entry) at most TOLERANCE. A file that shows another
# time's state, nodes out of order, another mode or misses the turning frame is off by the motion
# itself (relative 1e-2 to 1); the two formulations here differ only where the motion is
# nonlinear. Free vibration: the tip deflection is 1.9e-3 of the length, so its geometric
# nonlinearity is (1.9e-3)² ≈ 4e-6 of the motion: 1e-5 (measured 2026-11-27: 9.6e-9, rotations
# 3.4e-11). Modes about the undeformed state: linear, the same eigenproblem solved by two solvers
# to Ritz tolerance 1e-12: 1e-6 (measured 9.1e-10). Turning: the relative rotations stay below
# 7e-3 rad, so the formulations' nonlinear terms are ~1e-2 of the relative motion, itself a tenth
# of the inertial one (0.2 m against 2 m): 1e-3 (measured 1.1e-6, rotations 3.3e-6).
compare() {
    "$python" "$(dirname "$0")/vtk_compare.py" "$work/$1"/*.pvd "$work/$2"/*.pvd "$3" ||
        fail "$1 against $2: vtk_compare.py"
}
compare dynamic-linear dynamic-mixed 1e-5
compare modal modal-mixed 1e-6
compare turning-linear turning-mixed 1e-3
# What --vtk cannot write is refused before the run, with nothing written.
"$rotbeam" run cantilever-moment --accuracy 1e-3 --vtk "$work/refused" 2>"$work/err" >/dev/null
[ $? -eq 2 ] || fail "--vtk with --accuracy: not refused with exit 2"
[ ! -e "$work/refused" ] || fail "--vtk with --accuracy: files written"
exit $((failures > 0))
