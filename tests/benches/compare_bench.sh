#!/usr/bin/env bash
# scripts/compare-bench.py: a history file against itself has no flag (exit 0);
# a lost target, an error grown on the same discretization and a doubled time are each flagged
# (exit 1); another machine's file is refused (exit 2, one line).
src="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
compare="$src/scripts/compare-bench.py"
history=$(ls "$src"/reports/history/*.json | tail -1)

python3 "$compare" "$history" "$history" >"$work/same" 2>&1 || fail "a file against itself: $(tail -2 "$work/same")"
grep -q "^0 flag(s)" "$work/same" || fail "a file against itself is flagged"

python3 - "$history" "$work" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
reached = [r for t in d["targets"] for r in t["results"] if r.get("status") == "reached"
           and isinstance(r.get("winner"), dict) and "error" in r["winner"]]
reached[0]["winner"]["error"] = 1e-3
reached[1]["whole_process_seconds"] *= 2
reached[2]["status"] = "unreachable"
json.dump(d, open(sys.argv[2] + "/doctored.json", "w"))
d["machine"]["tag"] = "another-machine"
json.dump(d, open(sys.argv[2] + "/other.json", "w"))
PY
python3 "$compare" "$history" "$work/doctored.json" >"$work/doctored" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "doctored file exited $rc, expected 1"
[ "$(grep -c '^FLAG' "$work/doctored")" -eq 3 ] || fail "expected 3 flags: $(grep FLAG "$work/doctored")"
grep -q "error .* -> 0.001 on the same discretization" "$work/doctored" || fail "grown error not flagged"
grep -q "whole time 2.00×" "$work/doctored" || fail "doubled time not flagged"
grep -q "reached before, unreachable now" "$work/doctored" || fail "lost target not flagged"

python3 "$compare" "$history" "$work/other.json" >"$work/other" 2>"$work/other.err"
rc=$?
[ $rc -eq 2 ] || fail "another machine exited $rc, expected 2"
[ "$(wc -l <"$work/other.err")" -eq 1 ] && grep -q "machine.tag" "$work/other.err" ||
    fail "another machine: expected one line naming machine.tag: $(cat "$work/other.err")"
[ ! -s "$work/other" ] || fail "another machine: output written before the refusal"

if [ $failures -eq 0 ]; then echo "compare-bench: all checks passed"; exit 0; fi
exit 1
