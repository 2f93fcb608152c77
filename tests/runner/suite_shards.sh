#!/usr/bin/env bash
# Shards and merge (docs/distributed-runs.md), over `rotbeam suite --quick --no-studies` (its 20
# runs, ~5 s), the quick convergence study (242 independent runs and a combine step) and the quick
# joined-beam modal study (one whole study, so one of its two shards is empty), and the units of
# `study all` (the joined-beam studies, which share their references, are one):
# - three shards run one after another and merged give the same results as one run
#   (scripts/compare-results.py: equal JSON apart from the timing fields);
# - merge without one shard's folder exits 5, lists the missing runs with the command that makes
#   them, and writes nothing;
# - a shard killed with SIGKILL keeps its finished runs; merge lists the others; the same shard
#   started again makes only those (the finished files are not touched) and the merge is then the
#   same as one run;
# - a truncated result file, a damaged shard.json and a study record naming a file outside its
#   folder are refused with exit 2 and one line naming the file, and nothing is written.
# Usage: suite_shards.sh ROTBEAM COMPARE_RESULTS_PY
set -u
# rotbeam, compare; work (a scratch folder), fail and failures; same and complete_files.
. "$(dirname "$0")/results_check.sh" "$1" "$2"
set -m
suite=(suite --quick --no-studies --jobs 1)

"$rotbeam" "${suite[@]}" --out "$work/one" >/dev/null 2>&1 || fail "one suite failed"
for i in 1 2 3; do
    "$rotbeam" "${suite[@]}" --shard $i/3 --out "$work/s$i" >/dev/null 2>"$work/err$i.txt" ||
        fail "shard $i/3 failed: $(tail -1 "$work/err$i.txt")"
done
# The three shards hold every run once.
n=$(cat "$work"/s{1,2,3}/runs/*.json 2>/dev/null | grep -c '"input_key"')
total=$(ls "$work/one/runs" | grep -c '\.json$')
[ "$n" -eq "$total" ] || fail "the shards hold $n runs, one suite $total"
"$rotbeam" merge "$work/s1" "$work/s2" "$work/s3" --out "$work/merged" >/dev/null ||
    fail "merge failed"
same "$work/one" "$work/merged" "three shards merged"

# A shard missing: exit 5, its runs listed with the command that makes them, nothing written.
"$rotbeam" merge "$work/s1" "$work/s3" --out "$work/partial" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 5 ] || fail "merge without shard 2: exit $code, expected 5"
missing=$(ls "$work/s2/runs" | wc -l)
[ "$(grep -c '^  runs/.*\.json' "$work/err.txt")" -eq "$missing" ] ||
    fail "merge without shard 2 does not list its $missing runs: $(head -3 "$work/err.txt")"
grep -q -- "--shard 2/3" "$work/err.txt" || fail "merge without shard 2 names no command to run"
[ -e "$work/partial" ] && fail "merge without shard 2 wrote $work/partial"

# A shard killed with SIGKILL once two of its runs are written.
"$rotbeam" "${suite[@]}" --shard 1/3 --out "$work/k1" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 3000); do
    [ "$(ls "$work/k1/runs" 2>/dev/null | grep -c '\.json$')" -ge 2 ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.01
done
kill -KILL $pid 2>/dev/null
wait $pid
code=$?
finished=$(ls "$work/k1/runs" | grep -c '\.json$')
planned=$(ls "$work/s1/runs" | grep -c '\.json$')
if [ $code -eq 137 ] && [ "$finished" -lt "$planned" ]; then
    "$rotbeam" merge "$work/k1" "$work/s2" "$work/s3" --out "$work/after-kill" >/dev/null \
        2>"$work/err.txt"
    code=$?
    [ $code -eq 5 ] || fail "merge after SIGKILL: exit $code, expected 5"
    listed=$(grep -c '^  runs/.*\.json' "$work/err.txt")
    [ "$listed" -eq $((planned - finished)) ] ||
        fail "merge after SIGKILL lists $listed missing runs, expected $((planned - finished))"
    before=$(cd "$work/k1/runs" && stat -c '%n %y' *.json | sort)
    "$rotbeam" "${suite[@]}" --shard 1/3 --out "$work/k1" >/dev/null 2>&1 ||
        fail "shard 1/3 started again failed"
    while read -r name stamp; do
        [ "$(stat -c '%y' "$work/k1/runs/$name")" = "$stamp" ] || fail "finished run redone: $name"
    done <<<"$before"
    "$rotbeam" merge "$work/k1" "$work/s2" "$work/s3" --out "$work/after-kill" >/dev/null ||
        fail "merge after the killed shard was finished failed"
    same "$work/one" "$work/after-kill" "the killed shard, finished and merged"
    echo "SIGKILL: shard 1/3 stopped after $finished of $planned runs; started again, merged"
else
    echo "note: shard 1/3 finished ($finished of $planned runs, exit $code) before SIGKILL"
fi

# Damaged shard files are refused by name, with exit 2 and nothing written.
cp -r "$work/s3" "$work/c3"
victim=$(ls "$work/c3/runs" | head -1)
head -c 100 "$work/s3/runs/$victim" >"$work/c3/runs/$victim"
"$rotbeam" merge "$work/s1" "$work/s2" "$work/c3" --out "$work/corrupt" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] || fail "merge of a truncated run file: exit $code, expected 2"
[ "$(wc -l <"$work/err.txt")" -eq 1 ] || fail "truncated run file: not one line"
grep -q "c3/runs/$victim: not complete JSON" "$work/err.txt" ||
    fail "truncated run file not named: $(cat "$work/err.txt")"
[ -e "$work/corrupt" ] && fail "merge of a truncated run file wrote $work/corrupt"
cp -r "$work/s2" "$work/c2"
echo '{"format": "rotbeam-shard", "version":' >"$work/c2/shard.json"
"$rotbeam" merge "$work/s1" "$work/c2" "$work/s3" --out "$work/corrupt" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] || fail "merge of a damaged shard.json: exit $code, expected 2"
grep -q "c2/shard.json: not complete JSON" "$work/err.txt" ||
    fail "damaged shard.json not named: $(cat "$work/err.txt")"
[ -e "$work/corrupt" ] && fail "merge of a damaged shard.json wrote $work/corrupt"

# A split study (runs + combine) and a whole one over shards, against one run of each.
for study in convergence joined-beam-modal; do
    "$rotbeam" study $study --quick --out "$work/study-one-$study" >/dev/null 2>&1 ||
        fail "study $study failed"
    dirs=()
    for i in 1 2; do
        "$rotbeam" study $study --quick --jobs 1 --shard $i/2 --out "$work/study-$study-$i" \
            >/dev/null 2>&1 || fail "study $study shard $i/2 failed"
        dirs+=("$work/study-$study-$i")
    done
    "$rotbeam" merge "${dirs[@]}" --out "$work/study-merged-$study" >/dev/null ||
        fail "merge of study $study failed"
    same "$work/study-one-$study" "$work/study-merged-$study" "study $study over two shards"
done

# The two joined-beam studies share their references (joined-beam-references/): one unit, made in
# one folder one after the other, so that a shard computes them once. A shard of `study all` that
# gets no unit (1000 shards) and a merge of it list the job's units without running any.
"$rotbeam" study all --quick --shard 1000/1000 --out "$work/none" >/dev/null 2>&1 ||
    fail "study all shard 1000/1000 failed"
"$rotbeam" merge "$work/none" --out "$work/none-merged" >/dev/null 2>"$work/err.txt"
grep -q "studies/joined-beam.done.json (study joined-beam-dynamics + joined-beam-agreement)" \
    "$work/err.txt" || fail "the joined-beam studies are not one unit"
grep -q "studies/joined-beam-dynamics.done.json" "$work/err.txt" &&
    fail "joined-beam-dynamics is a unit of its own beside the pair"

# A whole study's record naming a file outside its folder (an absolute path, or `..`): merge copies
# the files a record lists into its output, so such a name would read and write elsewhere. It is
# refused by name, with exit 2 and nothing written.
echo "not a result" >"$work/outside.txt"
dirs=()
for i in 1 2; do
    d="$work/study-joined-beam-modal-$i"
    if [ -e "$d/studies/joined-beam-modal.done.json" ]; then
        cp -r "$d" "$work/escape"
        d="$work/escape"
        python3 - "$d/studies/joined-beam-modal.done.json" "$work/outside.txt" <<'PY'
import json, sys
record = json.load(open(sys.argv[1]))
record["files"].append(sys.argv[2])
json.dump(record, open(sys.argv[1], "w"))
PY
    fi
    dirs+=("$d")
done
"$rotbeam" merge "${dirs[@]}" --out "$work/escaped" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] || fail "merge of a study record naming $work/outside.txt: exit $code, expected 2"
grep -q "joined-beam-modal.done.json: files: \"$work/outside.txt\" is not a file name" \
    "$work/err.txt" || fail "study record naming a path outside: $(cat "$work/err.txt")"
[ -e "$work/escaped" ] && fail "merge of a study record naming a path outside wrote $work/escaped"

[ $failures -eq 0 ] && echo "shards: $total runs over three shards, merged = one run"
exit $((failures > 0))
