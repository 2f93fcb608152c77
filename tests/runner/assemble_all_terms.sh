#!/usr/bin/env bash
# solver.assemble_all_terms (core/model.hpp) assembles the terms a scene does not need with zero
# coefficients: the results must be those of the default run to round-off, and the counters must
# show the extra terms (otherwise the "time saved" of docs/studies.md measures nothing). Static,
# modal and dynamic analyses, both formulations.
set -u
rotbeam="$1"
cases="$2/cases"
# work (a scratch folder), fail and failures.
. "$(dirname "$0")/scratch.sh"

# case formulation rotation extra-set expected-extra-counter
while read -r case formulation rotation extra counter; do
    name="$case-$formulation-$rotation"
    args=(run "$cases/$case.yaml" --formulation "$formulation" --rotation "$rotation" --quiet --estimate off)
    [ "$extra" != "-" ] && args+=(--set "$extra")
    "$rotbeam" "${args[@]}" --json "$work/$name-needed.json" || fail "$name: default run"
    "$rotbeam" "${args[@]}" --set solver.assemble_all_terms=true \
        --json "$work/$name-all.json" || fail "$name: assemble_all_terms run"
    python3 - "$work/$name-needed.json" "$work/$name-all.json" "$counter" <<'PY' || fail "$name"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
counter = sys.argv[3]
solved = ("converged", "stalled-at-round-off")  # the latter: a residual at its round-off floor
assert a["status"] in solved and b["status"] in solved, (a["status"], b["status"])
assert b["options"]["assemble_all_terms"] is True
diff, size = 0.0, 0.0
def walk(x, y):
    global diff, size
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        diff = max(diff, abs(x - y)); size = max(size, abs(x)); return
    assert type(x) == type(y) and (not hasattr(x, "__len__") or len(x) == len(y))
    if isinstance(x, list):
        for u, v in zip(x, y): walk(u, v)
    elif isinstance(x, dict):
        for k in x: walk(x[k], y[k])
for key in ("steps", "frequencies_hz"):
    if key in a: walk(a[key], b[key])
assert size > 0 and diff <= 1e-12 * size, f"results differ: {diff} of {size}"
if counter != "-":
    assert a["counters"][counter] == 0, f"default assembled {counter}"
    assert b["counters"][counter] > 0, f"assemble_all_terms did not assemble {counter}"
PY
done <<'LIST'
cantilever-moment displacement quaternion - inertial_terms
cantilever-moment displacement rodrigues analysis.load_factors=[0.8] damping_terms
bend-45 displacement wiener-milenkovic - follower_stiffness
cantilever-moment mixed wiener-milenkovic analysis.load_factors=[0.8] inertial_terms
cantilever-moment mixed quaternion analysis.load_factors=[0.8] inertial_terms
bend-45 mixed rotation-vector - inertial_terms
joined-beam displacement rotation-vector - inertial_terms
joined-beam mixed wiener-milenkovic - -
blade-mh104 displacement quaternion analysis.end_time=0.02 damping_terms
joined-beam-follower mixed rotation-vector analysis.end_time=0.02 -
LIST

[ "$failures" -eq 0 ] && echo "assemble_all_terms: every result identical to round-off"
exit "$failures"
