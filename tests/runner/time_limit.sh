#!/usr/bin/env bash
# --time-limit of `suite` and `sweep` (docs/durability.md, "Time limit"):
# - a quick suite of the 45-degree bend with a limit of 1e-9 s: exit 0, every run's file has the
#   status time-limit, a message naming the limit, and no steps;
# - compare-results.py leaves those files out against the same suite without a limit (and says
#   how many), while it still finds a real difference in a file that is not time-limited;
# - the suite run again without the limit makes the stopped runs again (not up to date) and then
#   equals the suite made without a limit;
# - the sweep takes the same option, and a bad value is refused by `suite` and `sweep` like `run`.
# Usage: time_limit.sh ROTBEAM COMPARE_RESULTS_PY SOURCE_DIR
set -u
rotbeam=$1
compare=$2
src=$3
. "$(dirname "$0")/scratch.sh"
suite=(suite --quick --cases bend-45 --no-studies --estimate off --jobs 2)

"$rotbeam" "${suite[@]}" --time-limit 1e-9 --out "$work/limited" >/dev/null 2>"$work/err.txt"
code=$?
[ "$code" -eq 0 ] || fail "suite --time-limit exited $code: $(tail -1 "$work/err.txt")"
python3 - "$work/limited/runs" <<'PY' || fail "a run stopped by the suite's --time-limit does not say so"
import json, os, sys
names = sorted(os.listdir(sys.argv[1]))
assert len(names) == 10, names
for n in names:
    r = json.load(open(os.path.join(sys.argv[1], n)))
    assert r["status"] == "time-limit", (n, r["status"], r.get("message"))
    assert r["message"].startswith("the wall-clock limit of 1e-09 s was reached"), r["message"]
    assert r["steps"] == [], n
PY

"$rotbeam" "${suite[@]}" --out "$work/free" >/dev/null 2>&1 || fail "suite without a limit failed"
python3 - "$work/free/runs" <<'PY' || fail "the suite without a limit has time-limited runs"
import json, os, sys
for n in os.listdir(sys.argv[1]):
    assert json.load(open(os.path.join(sys.argv[1], n)))["status"] != "time-limit", n
PY
python3 "$compare" "$work/limited" "$work/free" >"$work/compare.txt" 2>&1 ||
    fail "compare-results did not leave the time-limited runs out: $(head -3 "$work/compare.txt")"
grep -q "^left out 10 JSON file(s) of runs stopped by the time limit (status time-limit)" \
    "$work/compare.txt" || fail "compare-results does not say what it left out: $(cat "$work/compare.txt")"
# Leaving out is not ignoring: a changed number in the one file compared is still found.
cp -r "$work/limited" "$work/changed"
python3 - "$work/changed/rotation-study.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
def bump(v):
    if isinstance(v, float):
        return v + 1.0
    if isinstance(v, list):
        return [bump(x) for x in v] if v else v
    if isinstance(v, dict):
        return {k: bump(x) for k, x in v.items()}
    return v
json.dump(bump(d), open(sys.argv[1], "w"))
PY
python3 "$compare" "$work/changed" "$work/free" >/dev/null 2>&1 &&
    fail "compare-results missed a difference in a file that was not time-limited"

# A rerun without the limit makes the stopped runs again: then it is the suite without a limit.
"$rotbeam" "${suite[@]}" --out "$work/limited" >/dev/null 2>&1 || fail "the rerun failed"
python3 "$compare" "$work/limited" "$work/free" >"$work/compare2.txt" 2>&1 ||
    fail "the rerun without a limit differs: $(head -3 "$work/compare2.txt")"
grep -q "^left out" "$work/compare2.txt" && fail "the rerun kept time-limited runs"

# The sweep: the same option, the same status.
"$rotbeam" sweep "$src/cases/sweeps/rollup-load-elements.yaml" --time-limit 1e-9 --jobs 2 \
    --out "$work/sweep" >/dev/null 2>"$work/err.txt" ||
    fail "sweep --time-limit exited $?: $(tail -1 "$work/err.txt")"
python3 - "$work/sweep/runs" <<'PY' || fail "a run stopped by the sweep's --time-limit does not say so"
import json, os, sys
names = sorted(os.listdir(sys.argv[1]))
assert len(names) == 24, names
for n in names:
    assert json.load(open(os.path.join(sys.argv[1], n)))["status"] == "time-limit", n
PY

# Bad values: the run's validation, naming the command; nothing written.
for command in suite sweep; do
    for v in 0 -1 nan 1e9 abc; do
        args=("${suite[@]:1}")
        [ "$command" = sweep ] && args=("$src/cases/sweeps/rollup-load-elements.yaml")
        out=$("$rotbeam" "$command" "${args[@]}" --time-limit "$v" --out "$work/never" 2>&1)
        code=$?
        [ "$code" -eq 2 ] || fail "$command --time-limit $v exited $code"
        [ "$out" = "rotbeam $command: --time-limit: expected a number in (0, 604800], got '$v'" ] ||
            fail "$command --time-limit $v: $out"
    done
done
[ ! -e "$work/never" ] || fail "a folder was written for a bad --time-limit"

exit $((failures > 0))
