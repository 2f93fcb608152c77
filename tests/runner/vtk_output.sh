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
# A dynamic run's estimate (space + time at every output time, docs/error-estimates.md) is point
# data of each output time's file like a static step's (vtk_check.py compares it with the JSON).
check dynamic-estimated free-vibration --set analysis.end_time=0.01
grep -q 'Name="estimate_displacement"' "$work/dynamic-estimated"/*_0010.vtu ||
    fail "dynamic-estimated: no estimate point data"
# The mixed runs beside a displacement run of the same linear discrete model (linear elements,
# one-point stiffness and mass: the mixed element, docs/displacement-modal.md), compared at their
# shared nodes (vtk_compare.py) in every file, the section resultants cell by cell.
linear=(--formulation displacement --order 1 --set discretization.mass_rule=midpoint
    --set discretization.quadrature=reduced)
# The section resultants against statics (vtk_equilibrium.py): a cantilever (L = 1 m) under a dead
# tip force P = 1 N along e3, at λ = 1 (tip deflection 0.2 % of L) and λ = 3000 (0.86 m): F = λP
# and M = (x_tip − x) × λP at every section, which the linear one-point displacement element and
# the mixed element satisfy exactly at a cell's midpoint (their discrete equilibrium); on the
# reference line M = −λP (L − x) e2 to within 2 max|u| λ|P|. Tolerance 1e-7 of λ|P| (of λ|P| L
# for M): the resultant is C [ε; κ] with EA = 2.1e7 N and ε formed from unit-size terms to a few
# ulps, ~2e-8 N of round-off, 2e-8 of the 1 N step (measured 2026-11-27: force 1.7e-9, moment
# 2.8e-16; Newton's scaled residual 6e-12). A resultant at the nodes instead of the midpoints is
# off by λP h/2 = 6e-2 λ|P| L, a material-axis one by the rotation (0.9 rad at λ = 3000).
tip=(--set 'analysis.load_factors=[1,3000]' --estimate off)
check static-tip-linear tip-load-cantilever "${linear[@]}" "${tip[@]}"
check static-tip-mixed tip-load-cantilever --formulation mixed "${tip[@]}"
for run in static-tip-linear static-tip-mixed; do
    "$python" "$(dirname "$0")/vtk_equilibrium.py" "$work/$run"/*.pvd 0,0,1 1e-7 ||
        fail "$run: section resultants against the tip force's statics"
done
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
# of the inertial one (0.2 m against 2 m): 1e-3 (measured 1.1e-6, rotations 3.3e-6). The tip
# force's statics: the same discrete equations solved by two Newton solvers, so they differ by
# the stopping and the round-off of the resultants (~2e-8 N against 3000 N): 1e-9 (measured
# positions 1.8e-16, force 4.4e-12, moment 4.2e-16). The section resultants (relative to each
# one's largest) are the positions' difference amplified: the shear force is kGA γ, γ formed from
# the difference of neighbouring nodes over h, so a difference δ of the positions moves it by
# kGA δ / h. Free vibration: kGA/h = 5.4e7 N/m, δ = 1.8e-11 m: 1e-3 N of a largest 2.9 N, 3e-4;
# tolerance 1e-3 (measured force 8.3e-5, moment 2.1e-8), while the resultants of the next output
# time differ by ~5 % (Δt = 1e-3 s of a 0.12 s period) and a neighbouring cell's moment by 1/8.
# Turning: within the motion's 1e-3 (measured force 6.2e-5, moment 6.0e-5).
compare() {
    "$python" "$(dirname "$0")/vtk_compare.py" "$work/$1"/*.pvd "$work/$2"/*.pvd "${@:3}" ||
        fail "$1 against $2: vtk_compare.py"
}
compare static-tip-linear static-tip-mixed 1e-9
compare dynamic-linear dynamic-mixed 1e-5 1e-3
compare modal modal-mixed 1e-6
compare turning-linear turning-mixed 1e-3
# What --vtk cannot write is refused before the run, with nothing written.
"$rotbeam" run cantilever-moment --accuracy 1e-3 --vtk "$work/refused" 2>"$work/err" >/dev/null
[ $? -eq 2 ] || fail "--vtk with --accuracy: not refused with exit 2"
[ ! -e "$work/refused" ] || fail "--vtk with --accuracy: files written"
exit $((failures > 0))
