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
check dynamic-mixed free-vibration --formulation mixed --rotation rotation-vector --estimate off \
    --set analysis.end_time=0.02 --set analysis.integrator=trapezoidal
grep -q 'Name="section_force"' "$work/dynamic-mixed"/*_0001.vtu ||
    fail "dynamic-mixed: no section_force cell data"
check modal joined-beam --formulation displacement --estimate off
check modal-mixed joined-beam --formulation mixed --estimate off
# A root turning at 1 rad/s about x: the inertial motion, the relative one as point data. The deck
# imported as a case file; its damping (which the mixed dynamics refuses) left out for the mixed run.
"$rotbeam" import beamdyn "$src/tests/data/beamdyn/rotating-cantilever/bd_driver.inp" \
    --out "$work/turning.yaml" >/dev/null || fail "import of the turning deck"
check turning-displacement "$work/turning.yaml" --estimate off
grep -v '^ *damping:' "$work/turning.yaml" >"$work/turning-undamped.yaml"
check turning-mixed "$work/turning-undamped.yaml" --formulation mixed --estimate off \
    --set analysis.integrator=trapezoidal
# What --vtk cannot write is refused before the run, with nothing written.
"$rotbeam" run cantilever-moment --accuracy 1e-3 --vtk "$work/refused" 2>"$work/err" >/dev/null
[ $? -eq 2 ] || fail "--vtk with --accuracy: not refused with exit 2"
[ ! -e "$work/refused" ] || fail "--vtk with --accuracy: files written"
exit $((failures > 0))
