#!/usr/bin/env bash
# The rotbeam program's contract (docs/architecture.md, The program and its results), checked on the built
# executable. Usage: program_contract.sh ROTBEAM SOURCE_DIR
set -u
rotbeam=$1
src=$2
# work (a scratch folder), fail and failures.
. "$(dirname "$0")/scratch.sh"

# expect_input_error DESCRIPTION ARGS...: exit code 2, exactly one line on stderr, nothing on stdout.
expect_input_error() {
    local what=$1
    shift
    "$rotbeam" "$@" >"$work/out" 2>"$work/err"
    local rc=$?
    [ $rc -eq 2 ] || fail "$what: exit $rc, expected 2"
    [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$what: stderr has $(wc -l <"$work/err") lines: $(cat "$work/err")"
    [ ! -s "$work/out" ] || fail "$what: wrote to stdout"
}

# Usage errors.
expect_input_error "no command"
expect_input_error "unknown command" frobnicate
# A name far from every command: the message names it and suggests nothing.
grep -q "unknown command 'frobnicate'" "$work/err" || fail "frobnicate not named: $(cat "$work/err")"
if grep -q "did you mean" "$work/err"; then fail "a suggestion for 'frobnicate': $(cat "$work/err")"; fi
expect_input_error "misspelt command" verfy
grep -q "did you mean 'verify'" "$work/err" || fail "no suggestion for 'verfy': $(cat "$work/err")"
expect_input_error "unknown option" run cantilever-moment --rotaton quaternion
grep -q "did you mean '--rotation'" "$work/err" || fail "no suggestion for --rotaton"
expect_input_error "zero elements" run cantilever-moment --elements 0
expect_input_error "missing case" run no-such-case.yaml
expect_input_error "unknown parameterization" run cantilever-moment --rotation cayley --json "$work/r.json"
[ ! -e "$work/r.json" ] || fail "a result file was written for bad input"
expect_input_error "bad --estimate" run cantilever-moment --estimate maybe --json "$work/r.json"
grep -q -- "--estimate" "$work/err" || fail "bad --estimate not named: $(cat "$work/err")"
[ ! -e "$work/r.json" ] || fail "a result file was written for a bad --estimate"
# --accuracy goes through the loader like the key it sets (analysis.accuracy, its range), and
# needs the estimate (docs/accuracy-control.md).
expect_input_error "bad --accuracy" run cantilever-moment --accuracy 2 --json "$work/r.json"
grep -q "analysis.accuracy" "$work/err" || fail "bad --accuracy not named: $(cat "$work/err")"
expect_input_error "--accuracy with --estimate off" run cantilever-moment --accuracy 1e-6 \
    --estimate off --json "$work/r.json"
[ ! -e "$work/r.json" ] || fail "a result file was written for a bad --accuracy"
expect_input_error "unknown study" study nothing
# A newline or another control character in what the user wrote is escaped: still one line.
expect_input_error "a command with a newline" $'fro\nbnicate'
grep -q "unknown command 'fro\\\\nbnicate'" "$work/err" || fail "newline not escaped: $(cat "$work/err")"
expect_input_error "a case name with a newline" run $'no-such\ncase.yaml'
expect_input_error "an option value with a newline" run cantilever-moment --rotation $'quater\nnion'
# Every command-line value goes through the validation of the case file, with the same limits
# (docs/case-format.md, Limits): negative, zero, non-numeric, fractional, overflowing, NaN/inf,
# past a limit, unknown keys; refused with one line before anything runs or is written.
expect_bad_value() {
    local what=$1 fragment=$2
    shift 2
    expect_input_error "$what" "$@"
    grep -qF -- "$fragment" "$work/err" || fail "$what: '$(cat "$work/err")' lacks '$fragment'"
}
for v in -3 abc 2.5 99999999999 .nan .inf "[1, 2]"; do
    expect_bad_value "--elements $v" "members.beam.elements: " run cantilever-moment --elements "$v"
done
# A value with a control byte is refused in the words of a value, naming the option the user
# typed (a shorthand) or --set with the key, never in the words of a case file.
expect_bad_value "a parameterization with a tab and a bell" \
    ":--rotation: discretization.rotation: the value holds a control character or a byte that is not UTF-8 (byte 3)" \
    run cantilever-moment --rotation $'a\tb\a'
expect_bad_value "a --set value with a control byte" \
    ":--set: discretization.rotation: the value holds a control character" \
    check cantilever-moment --set $'discretization.rotation=qua\001ternion'
expect_bad_value "--elements with a non-UTF-8 byte" \
    ":--elements: members.*.elements: the value holds a control character or a byte that is not UTF-8 (byte 1)" \
    run cantilever-moment --elements $'4\xff'
expect_bad_value "a shorthand's value refused by the validation" \
    ":--elements: members.beam.elements: must be a positive integer" run cantilever-moment --elements 0
expect_bad_value "--elements past its limit" "members.beam.elements: must be at most 100000" \
    run cantilever-moment --elements 100001
expect_bad_value "--order 400" "discretization.order: must be at most 24" \
    run cantilever-moment --order 400
expect_bad_value "--order 0" "discretization.order: must be a positive integer" \
    check cantilever-moment --set discretization.order=0
expect_bad_value "--set NaN" "must be finite, got '.nan'" \
    check cantilever-moment --set sections.square.isotropic.E=.nan
expect_bad_value "--set -inf" "must be finite" check cantilever-moment --set 'points.tip=[-.inf, 0, 0]'
expect_bad_value "--set unknown key" "discretization.ordr: unknown key; did you mean 'order'?" \
    check cantilever-moment --set discretization.ordr=2
expect_bad_value "--set substeps past the limit" "analysis.substeps: must be at most 100000" \
    check cantilever-moment --set analysis.substeps=1000000
expect_bad_value "--set modal memory" "the run would need an estimated" \
    check free-vibration --set analysis.time_step=0.1 --set analysis.end_time=0.1 \
    --set 'members.*.elements=100000' --set solver.linear_solver=dense
expect_bad_value "--set recursive alias" "the value: alias *a is inside the node its anchor names" \
    check cantilever-moment --set 'points.tip=&a [*a]'
expect_bad_value "--set '*' on a value" "'*' must stand for the keys of an existing mapping" \
    check cantilever-moment --set 'gravity.*.x=1'
# A bad item of a list given with --set is named at `:--set:`, not at a line of the file.
expect_bad_value "--set list item" ":--set: analysis.load_factors[0]: " \
    check cantilever-moment --set 'analysis.load_factors=[nan]'
# The case name becomes part of the output files' names (docs/case-format.md, Top level): a name
# that would leave --out, hide the file or name nothing is refused by check and by run, and
# nothing is written.
mkdir -p "$work/names/out"
for n in ../../escaped '""' 'beam 1/2' .hidden; do
    expect_bad_value "check --set name=$n" ":--set: name: " check cantilever-moment --set "name=$n"
    grep -qF "cannot be part of a file name" "$work/err" || fail "name=$n: $(cat "$work/err")"
    expect_bad_value "run --set name=$n" ":--set: name: " run cantilever-moment --set "name=$n" \
        --estimate off --quiet --out "$work/names/out"
done
[ -z "$(find "$work/names" "$work" -maxdepth 1 -name '*escaped*')" ] &&
    [ -z "$(ls -A "$work/names/out")" ] || fail "a refused case name wrote files"
for v in 0 -1 abc 1.5 99999999999 nan 257; do
    expect_bad_value "suite --jobs $v" "--jobs: expected an integer from 1 to 256, got '$v'" \
        suite --jobs "$v" --out "$work/never"
done
[ ! -e "$work/never" ] || fail "suite with a bad --jobs created its output folder"
expect_bad_value "bench --repeats 0" "--repeats: expected an integer from 1 to 1000" \
    bench --repeats 0 --json "$work/never.json"
expect_bad_value "bench --targets unknown" "--targets: unknown target 'joined-beam-modl'; did you mean 'joined-beam-modal'?" \
    bench --targets joined-beam-modl --json "$work/never.json"
[ ! -e "$work/never.json" ] || fail "bench with an unknown target wrote a result"
expect_bad_value "suite --cases matching nothing" "--cases: 'zzz*' matches no catalog case" \
    suite --cases 'zzz*' --out "$work/never"
[ ! -e "$work/never" ] || fail "suite matching no case created its output folder"
expect_bad_value "study --samples 1" "--samples: expected an integer from 2 to 20000, got '1'" \
    study rotations --samples 1
# The wall-clock limit: its own status, no steps, no NaN, exit 0; a bad value is an input error.
"$rotbeam" run joined-beam-dead --time-limit 0.05 --json "$work/limited.json" >/dev/null 2>&1 ||
    fail "run --time-limit exited $?"
python3 - "$work/limited.json" <<'PY' || fail "a run stopped by --time-limit does not say so"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "time-limit", r["status"]
assert "wall-clock limit of 0.05 s was reached" in r["message"], r["message"]
assert r["steps"] == [], "steps kept"
PY
for v in 0 -1 nan inf abc 1e9; do
    expect_bad_value "--time-limit $v" "--time-limit: expected a number in (0, 604800], got '$v'" \
        run cantilever-moment --time-limit "$v" --json "$work/never.json"
done
[ ! -e "$work/never.json" ] || fail "a result was written for a bad --time-limit"
# A model the formulation refuses (a rigid section in the displacement formulation): one line
# naming the file.
sed 's/isotropic: {E: 1.0e7, nu: 0.3, A: 1.0, I2: 0.0833, I3: 0.0833, J: 0.14}/compliance: [[1, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]]/' \
    "$src/cases/bad/zero-elements.yaml" | sed 's/elements: 0/elements: 2/' >"$work/rigid.yaml"
expect_bad_value "rigid section, displacement" "rigid.yaml: (model): member 'beam': the displacement" \
    run "$work/rigid.yaml" --json "$work/never.json"
[ ! -e "$work/never.json" ] || fail "a result was written for a refused model"
# A file past the size limit, and one of non-UTF-8 text: one line naming the file.
head -c 1048577 /dev/zero | tr '\0' '#' >"$work/huge.yaml"
expect_bad_value "file past the size limit" "huge.yaml:1: (file): larger than 1048576 bytes" \
    check "$work/huge.yaml"
printf 'name: caf\xe9\n' >"$work/latin.yaml"
expect_bad_value "non-UTF-8 file" "latin.yaml:1: (file): not a text case file" check "$work/latin.yaml"

# Every command has --help (exit 0).
for c in list check run suite verify reference study; do
    "$rotbeam" $c --help >/dev/null 2>&1 || fail "$c --help failed"
done

# Bad case files: one line naming the file, exit 2, no result file.
count=0
for f in "$src"/cases/bad/*.yaml; do
    [ -e "$f" ] || continue
    count=$((count + 1))
    expect_input_error "check $(basename "$f")" check "$f"
    grep -q "$(basename "$f")" "$work/err" || fail "$(basename "$f"): message does not name the file: $(cat "$work/err")"
    expect_input_error "run $(basename "$f")" run "$f" --json "$work/bad.json"
    [ ! -e "$work/bad.json" ] || fail "$(basename "$f"): partial result written"
done
[ $count -ge 20 ] || fail "only $count bad case files (need at least 20)"

# --frame beamdyn needs a BeamDyn driver file.
expect_input_error "run --frame beamdyn on a yaml" run cantilever-moment --frame beamdyn \
    --json "$work/bad.json"
grep -q -- "--frame beamdyn" "$work/err" || fail "--frame beamdyn: message does not name it"
[ ! -e "$work/bad.json" ] || fail "--frame beamdyn: partial result written"

# list names every parameterization and formulation.
"$rotbeam" list >"$work/list" || fail "list failed"
for name in quaternion wiener-milenkovic rodrigues rotation-vector euler-angles displacement mixed \
    cantilever-moment bend-45; do
    grep -qw -- "$name" "$work/list" || fail "list does not show $name"
done

# A run writes the JSON contract.
"$rotbeam" run cantilever-moment --quiet --json "$work/run.json" || fail "run failed"
python3 - "$work/run.json" <<'PY' || fail "run JSON does not follow the contract"
import json, sys
r = json.load(open(sys.argv[1]))
for k in ["case", "rotation", "formulation", "elements", "order", "dofs", "status", "message",
          "wall_seconds", "steps"]:
    assert k in r, k
# The displacement formulation's residual floor on the roll-up (~7e-11 scaled) is above the case's
# 1e-12: its steps meet the tolerances or stall at that floor, and each says which and how well.
assert r["status"] in ("converged", "stalled-at-round-off"), r["message"]
if r["status"] == "stalled-at-round-off":
    assert "expected floor" in r["message"], r["message"]
for s in r["steps"]:
    c = s["convergence"]
    assert c["criterion"] in ("exact", "residual-and-correction", "stalled-at-round-off"), c
    assert 0 <= c["error_bound"] <= r["options"]["increment_tolerance"], c
    assert c["criterion"] == "stalled-at-round-off" or c["scaled_residual"] <= r["options"]["residual_tolerance"], c
p = r["steps"][-1]["points"]["tip"]
assert len(p["displacement"]) == 3 and len(p["rotation_matrix"]) == 3 and len(p["rotation_vector"]) == 3
assert "rotation_angle" in p and "load_factor" in r["steps"][-1] and "newton_iterations" in r["steps"][-1]
# The error estimate (docs/error-estimates.md): on by default, p+1 for the displacement
# formulation, every step's points estimated, its cost recorded.
e = r["estimate"]
assert e["status"] == "estimated" and e["method"] == "p+1", e
assert e["companions"][0]["order"] == r["order"] + 1 and e["wall_seconds"] > 0, e
for s in r["steps"]:
    q = s["estimate"]["tip"]["displacement"]
    assert q["error"] >= 0 and q["reliable"] in (True, False), q
PY
"$rotbeam" run cantilever-moment --quiet --estimate off --json "$work/off.json" || fail "run --estimate off failed"
python3 - "$work/off.json" <<'PY' || fail "run --estimate off still estimates"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["estimate"] == {"status": "off"}, r["estimate"]
assert all("estimate" not in s for s in r["steps"])
PY

# KINSOL drives the additive (mixed) formulation through the same load stepping, and is refused
# for a multiplicative update.
"$rotbeam" run cantilever-moment --formulation mixed --rotation wiener-milenkovic --elements 16 \
    --set solver.driver=kinsol --set 'analysis.load_factors=[0.4,1.6]' --quiet --json "$work/kin.json" \
    || fail "kinsol run failed"
python3 - "$work/kin.json" <<'PY' || fail "kinsol run did not reproduce Table I at lambda = 1.6"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "converged", r["message"]
u = r["steps"][-1]["points"]["tip"]["displacement"]
assert abs(u[0] + 14.2403) < 1e-4 and abs(u[2] - 1.6287) < 1e-4, u
# Section resultants along the beam: the pure tip moment is carried unchanged (1.6·(−πEI/L) about
# y, a rotation about y leaves the material y axis in place) with no force, at 16 stations.
sec = r["section_resultants"]
assert sec["load_factor"] == 1.6 and len(sec["stations"]) == 16, sec
for st in sec["stations"]:
    for key in ("moment", "moment_material"):
        assert abs(st[key][1] - 1.6 * -654498.4694978736) < 1e-6 * 654498.0, st
    assert max(abs(f) for f in st["force"]) < 1e-6, st
PY
expect_input_error "kinsol with rotations composed" run cantilever-moment --set solver.driver=kinsol

# The mixed formulation with the quaternion (four-component Eq. 48): the roll-up to λ = 4 on the
# case's 16 elements, 20N + 6 unknowns, the norm drift in the message. Each element turns its end
# node by the Cayley angle 4 atan(δ/4), δ = π/4, so the unwrapped tip angle is 16 · 4 atan(π/16)
# = 4π − (4π)³/(48·16²) + 3.7e-3 (the next series term): 1e-2 separates it from 4π by 16×. The
# equality to 1e-9 rad allows the case's Newton tolerance (1e-12 scaled) times the angle's
# condition, with a margin of ≥ 100.
"$rotbeam" run cantilever-moment-4 --formulation mixed --rotation quaternion --quiet \
    --json "$work/quat.json" || fail "mixed quaternion run failed"
python3 - "$work/quat.json" <<'PY' || fail "mixed quaternion run does not follow the contract"
import json, math, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "converged" and r["formulation"] == "mixed", r["message"]
assert r["rotation"] == "quaternion" and r["dofs"] == 20 * 16 + 6, r["dofs"]
assert "nodes" in r["message"] and "elements" in r["message"], r["message"]
tip = r["steps"][-1]["points"]["tip"]
assert r["steps"][-1]["load_factor"] == 4.0
assert abs(tip["rotation_angle"] - 64 * math.atan(math.pi / 16)) < 1e-9, tip["rotation_angle"]
assert abs(tip["rotation_angle"] - (4 * math.pi - (4 * math.pi) ** 3 / (48 * 256))) < 1e-2
PY

# A dynamic run (displacement formulation) writes `time` steps and a CSV history next to its JSON
# with the points, the support reactions and the energies; the supports pull down while the
# joint force pushes up (the rest of F_z is still inertia at t = 10 ms, a third of the 35 Hz
# first period).
"$rotbeam" run joined-beam-follower --rotation wiener-milenkovic --set analysis.end_time=0.01 \
    --json "$work/dyn.json" >/dev/null 2>&1 || fail "dynamic run exited non-zero"
[ -s "$work/dyn.csv" ] || fail "dynamic run wrote no CSV history"
# The estimate (on by default) adds its columns last: in space (p+1), in time (dt/2) and combined.
head -1 "$work/dyn.csv" |
    grep -q "^time,.*joint_uz.*root1_Fz.*kinetic_energy,strain_energy,joint_u_err_p+1\[length\],joint_u_err_dt/2\[length\],joint_u_err\[length\],.*root2_angle_err\[rad\]$" ||
    fail "CSV header lacks the joint, reaction, energy or estimate columns: $(head -1 "$work/dyn.csv")"
[ "$(wc -l <"$work/dyn.csv")" -eq 12 ] || fail "CSV should hold t = 0 … 0.01 s at 1 ms (11 rows)"
python3 - "$work/dyn.json" <<'PY' || fail "dynamic run JSON does not follow the contract"
import json, math, sys
r = json.load(open(sys.argv[1]))
assert r["status"] in ("converged", "stalled-at-round-off"), r["message"]
assert [round(s["time"], 9) for s in r["steps"]] == [round(0.001 * k, 9) for k in range(11)]
last = r["steps"][-1]
Fz = 1e5 * math.sin(20 * last["time"])
reaction_z = sum(last["reactions"][p]["force"][2] for p in ("root1", "root2"))
assert last["points"]["joint"]["displacement"][2] > 0
assert -Fz < reaction_z < 0.0, (reaction_z, Fz)
assert r["counters"]["inertial_terms"] > 0 and r["counters"]["damping_terms"] == 0
PY

# The gate can fail: a deliberately wrong published value (in the references file beside the case,
# cases/references/) makes verify exit 1; run does not read that file, so a broken one stops verify
# (exit 2, naming it) and not run. Each check's references file holds only the entry it breaks,
# selecting one combination: verify runs only the combinations its entries select, and the whole
# catalog file (every combination of the case to λ = 2, once per check) was ~150 of this test's
# ~163 s under the sanitizers (docs/quality-checks.md, Time). The gate's logic is the same for one
# entry as for many; that every catalog entry passes is published_gate's check, and every
# combination runs sanitized in scripts/asan.sh's `suite --quick`.
mkdir -p "$work/references"
cp "$src/cases/cantilever-moment.yaml" "$work/wrong.yaml"
gate_fails() {  # gate_fails WHAT ROW: verify exits 1 and prints a FAIL row matching ROW
    "$rotbeam" verify "$work/wrong.yaml" >"$work/verify" 2>&1
    local rc=$?
    [ $rc -eq 1 ] || fail "verify with $1 exited $rc, expected 1: $(tail -3 "$work/verify")"
    grep -q "$2.*FAIL" "$work/verify" ||
        fail "$1 is not a FAIL row: $(grep -v '^$' "$work/verify" | head -3)"
}
# A published value the run misses (Table I's analytical tip at λ = 0.4 is [-2.918, 6.598]).
cat >"$work/references/wrong.yaml" <<'YAML'
references:
  wrong-value:
    quantity: displacement
    point: tip
    load_factor: 0.4
    components: [0, 2]
    value: [1000.0, 1000.0]
    tolerance: 1.0e-9
    justification: test
    source: test
    applies_to: {formulation: displacement, rotation: quaternion, interpolation: relative}
    scope: test
YAML
gate_fails "a wrong reference" "wrong-value .*displacement/quaternion/relative"
# An unavailable result is a miss, not a skip: a discretization the program refuses (the mixed
# formulation has no lumped mass) selected by a reference fails the gate.
cat >"$work/references/wrong.yaml" <<'YAML'
references:
  refused:
    quantity: displacement
    point: tip
    load_factor: 0.4
    components: [0, 2]
    value: [-2.9180792563, 6.5984016563]
    tolerance: 0.1
    justification: test
    source: test
    applies_to: {formulation: mixed, mass_rule: lumped}
    scope: test
YAML
gate_fails "an unavailable combination" "refused .*unavailable: "
# A change in reach is caught both ways: an expected stop that the combination passes (mixed WM
# does converge at 1.6) and one with another status fail the gate. The catalog's entries, changed.
stop_entry() {  # stop_entry NAME: the catalog's expected stop NAME alone, as a references file
    echo "expected_stops:"
    sed -n "/^  $1:/,/^  [a-z]/p" "$src/cases/references/cantilever-moment.yaml" |
        sed '2,$ { /^  [a-z]/d }'
}
stop_entry mixed-wm-plain |
    sed -E 's/reaches: 1.6/reaches: 1.2/; s/stops_before: 1.96/stops_before: 1.6/' \
        >"$work/references/wrong.yaml"
grep -q "reaches: 1.2" "$work/references/wrong.yaml" || fail "no mixed-wm-plain stop to change"
gate_fails "a stop the combination passes" "mixed-wm-plain "
stop_entry mixed-rodrigues | sed -E 's/status: diverged/status: singular/' \
    >"$work/references/wrong.yaml"
grep -q "status: singular" "$work/references/wrong.yaml" || fail "no mixed-rodrigues stop to change"
gate_fails "a stop of another status" "mixed-rodrigues "
sed -E '0,/point: tip/s/point: tip/point: nowhere/' "$src/cases/references/cantilever-moment.yaml" >"$work/references/wrong.yaml"
"$rotbeam" verify "$work/wrong.yaml" >"$work/verify" 2>"$work/verify.err"
rc=$?
[ $rc -eq 2 ] || fail "verify with a broken references file exited $rc, expected 2"
grep -q "^$work/references/wrong.yaml:[0-9]*: references\." "$work/verify.err" ||
    fail "a broken references file is not named with its line: $(cat "$work/verify.err")"
"$rotbeam" run "$work/wrong.yaml" --quiet --set analysis.load_factors=[0.4] >/dev/null 2>&1 ||
    fail "run read the references file beside the case"

if [ $failures -eq 0 ]; then echo "program contract: all checks passed"; exit 0; fi
echo "program contract: $failures failures"
exit 1
