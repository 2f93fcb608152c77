#!/usr/bin/env bash
# Damaged result files read back (runs/run_file.hpp, docs/durability.md "Resume"): a resumed
# suite and `rotbeam merge` refuse each damage with exit 2 and ONE line naming the file and the
# JSON key, and write nothing (the suite leaves its folder as it was, the merge creates no
# output); `merge` of one folder given twice and `sweep --list` with a bad --shard are refused the
# same way. Over `suite --quick --cases bend-45 --no-studies --estimate off` (10 static runs).
# Usage: run_file_damage.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work (a scratch folder), fail and failures.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
suite=(suite --quick --cases bend-45 --no-studies --estimate off --jobs 1)

"$rotbeam" "${suite[@]}" --out "$work/su" >/dev/null 2>&1 || fail "the suite failed"
"$rotbeam" "${suite[@]}" --shard 1/1 --out "$work/shd" >/dev/null 2>&1 || fail "shard 1/1 failed"
name=bend-45_quaternion_displacement.json
[ -s "$work/su/runs/$name" ] || fail "the suite wrote no $name"
[ -s "$work/shd/runs/$name" ] || fail "the shard wrote no $name"
cp "$work/su/runs/$name" "$work/good.json"

# damage FILE WHAT: writes into FILE the good result damaged as WHAT says (a Python statement on
# the parsed result `j`, or `cut` for the file cut after 500 bytes, or `overflow` for a load
# factor written as 1e999, a number beyond the double range).
damage() {
    python3 - "$work/good.json" "$1" "$2" <<'PY'
import json, re, sys
good, target, what = sys.argv[1:]
text = open(good).read()
if what == "cut":
    out = text[:500]
elif what == "overflow":
    out = re.sub(r'"load_factor": [-0-9.e]+', '"load_factor": 1e999', text, count=1)
else:
    j = json.loads(text)
    exec(what)
    out = json.dumps(j, indent=1) + "\n"
open(target, "w").write(out)
PY
}

# refused WHAT KEY ERR CODE: exit 2 and one line naming the damaged file and KEY.
refused() {
    [ "$4" -eq 2 ] || fail "$1: exit $4, expected 2: $(head -2 "$3")"
    [ "$(wc -l <"$3")" -eq 1 ] || fail "$1: not one line: $(head -3 "$3")"
    grep -qF "runs/$name: $2" "$3" || fail "$1: the file and '$2' not named: $(cat "$3")"
}

# The damages: what is done to the result, the key the refusal must name.
damages=(
    "j['status'] = 5|status: expected a string"
    "del j['steps']|steps: missing"
    "j['steps'][1]['load_factor'] = 'a'|steps[1].load_factor: expected a finite number"
    "j['steps'][0]['points']['tip']['displacement'] = [0, 1]|steps[0].points.tip.displacement: expected 3 numbers"
    "del j['steps'][2]['points']|steps[2].points: missing"
    "j['schema_version'] = 2|schema_version:"
    "j['input_key'] = 7|input_key: expected a string"
    "j['wall_seconds'] = None|wall_seconds: expected a finite number"
    "j['options'] = []|options: expected an object"
    "j = [j]|(top level): expected a JSON object"
    "overflow|not valid JSON"
    "cut|not complete JSON"
)
listing() { (cd "$1" && find . -type f -printf '%p %s %T@\n' | sort); }
for entry in "${damages[@]}"; do
    what=${entry%%|*}
    key=${entry#*|}
    # A resumed suite: refused, the folder left as it was (nothing run, nothing written).
    damage "$work/su/runs/$name" "$what"
    before=$(listing "$work/su")
    "$rotbeam" "${suite[@]}" --out "$work/su" >/dev/null 2>"$work/err.txt"
    refused "suite over '$what'" "$key" "$work/err.txt" $?
    grep -q "delete it" "$work/err.txt" || fail "suite over '$what': does not say to delete it"
    [ "$(listing "$work/su")" = "$before" ] || fail "suite over '$what' changed its folder"
    # A merge of a shard folder: refused, no output.
    damage "$work/shd/runs/$name" "$what"
    rm -rf "$work/merged"
    "$rotbeam" merge "$work/shd" --out "$work/merged" >/dev/null 2>"$work/err.txt"
    refused "merge over '$what'" "$key" "$work/err.txt" $?
    [ -e "$work/merged" ] && fail "merge over '$what' wrote $work/merged"
done

# The good file back: the suite resumes (nothing to run) and the merge writes its output.
cp "$work/good.json" "$work/su/runs/$name"
cp "$work/good.json" "$work/shd/runs/$name"
"$rotbeam" "${suite[@]}" --out "$work/su" >/dev/null 2>&1 || fail "the suite over good files failed"
cmp -s "$work/good.json" "$work/su/runs/$name" || fail "the resumed suite remade a good run"
"$rotbeam" merge "$work/shd" --out "$work/merged" >/dev/null 2>&1 || fail "merge of good files failed"

# One folder given twice (under two names): its runs would count twice.
"$rotbeam" merge "$work/shd" "$work/shd/" --out "$work/twice" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] || fail "merge of one folder twice: exit $code, expected 2"
[ "$(wc -l <"$work/err.txt")" -eq 1 ] || fail "merge of one folder twice: not one line"
grep -q "given twice" "$work/err.txt" || fail "merge of one folder twice: $(cat "$work/err.txt")"
[ -e "$work/twice" ] && fail "merge of one folder twice wrote $work/twice"

# --shard is checked with --list as without it.
sweep=${ROTBEAM_CASES:-cases}/sweeps/rollup-load-elements.yaml
for shard in 0/2 3/2 x; do
    "$rotbeam" sweep "$sweep" --list --shard "$shard" >/dev/null 2>"$work/err.txt"
    code=$?
    [ $code -eq 2 ] || fail "sweep --list --shard $shard: exit $code, expected 2"
    grep -q -- "--shard: '$shard'" "$work/err.txt" ||
        fail "sweep --list --shard $shard: $(cat "$work/err.txt")"
done

[ $failures -eq 0 ] && echo "damaged result files: ${#damages[@]} damages refused by suite and merge"
exit $((failures > 0))
