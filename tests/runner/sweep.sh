#!/usr/bin/env bash
# `rotbeam sweep FILE` (docs/sweeps.md) on the example cases/sweeps/rollup-load-elements.yaml (the
# roll-up at 4 load factors × 3 meshes × 2 parameterizations, 24 runs, ~5 s):
# - it expands to the 24 runs the file describes, in the documented order (the list below is
#   written from the file by hand, not produced by rotbeam); so do a zipped sweep with ranges and
#   an interpolation list, and a sweep without combinations (every one the case takes);
# - each run's result equals `rotbeam run CASE --formulation F --rotation R --set KEY=VALUE ...`
#   (scripts/compare-results.py: equal JSON apart from the timings; the sweep's own input_key
#   removed);
# - the sweep table has the swept keys as columns and one row per run and named point;
# - a rerun makes nothing again (the run files are not rewritten);
# - three shards merged equal one run (the results, and sweep.csv byte for byte); a sweep file
#   changed or gone since the shards is refused by merge, naming it;
# - every bad sweep file of cases/bad-sweeps/ is refused with exit 2 and one line naming the file
#   and the key (cases/bad-sweeps/expected.txt), and nothing is written.
# Usage: sweep.sh ROTBEAM COMPARE_RESULTS_PY SOURCE_DIR
set -u
rotbeam=$1
compare=$2
src=$3
. "$(dirname "$0")/scratch.sh"
. "$(dirname "$0")/results_check.sh"
file=$src/cases/sweeps/rollup-load-elements.yaml

# The expansion: case × formulation × rotation, then the keys' product, the last key fastest.
"$rotbeam" sweep "$file" --list --out "$work/one" >"$work/list.txt" 2>&1 || fail "--list failed"
n=0
for rotation in quaternion wiener-milenkovic; do
    for lf in 0.5 1.0 1.5 2.0; do
        for e in 2 4 8; do
            n=$((n + 1))
            printf 'rollup-load-elements-%04d_cantilever-moment_%s_displacement.json: cantilever-moment displacement/%s analysis.load_factors=%s members.*.elements=%s\n' \
                $n "$rotation" "$rotation" "$lf" "$e"
        done
    done
done >"$work/expected-list.txt"
echo "rotbeam sweep: $file: 24 runs" >>"$work/expected-list.txt"
diff "$work/expected-list.txt" "$work/list.txt" >"$work/list-diff.txt" ||
    fail "the expansion differs from the file's 24 runs: $(head -4 "$work/list-diff.txt")"
[ -e "$work/one" ] && fail "--list wrote $work/one"

# Zipped keys, integer ranges, logspace and an interpolation list (which the mixed formulation
# does not take: its runs keep the case's own); a catalog case without combinations gets every
# formulation × parameterization it takes (2 × 5).
cat >"$work/zipped.yaml" <<'YAML'
name: zipped
cases: [bend-45]
combinations:
  formulation: [displacement, mixed]
  rotation: rodrigues
  interpolation: [relative, direct]
combine: zip
parameters:
  discretization.order: {range: [2, 6, 2]}
  solver.residual_tolerance: {logspace: [-10, -8, 3]}
YAML
{
    n=0
    for run in "displacement discretization.interpolation=relative " "displacement discretization.interpolation=direct " "mixed "; do
        set -- $run
        for pair in "2 1e-10" "4 1e-09" "6 1e-08"; do
            set -- $run $pair
            n=$((n + 1))
            if [ $# -eq 4 ]; then
                printf 'zipped-%04d_bend-45_rodrigues_%s.json: bend-45 %s/rodrigues %s discretization.order=%s solver.residual_tolerance=%s\n' $n "$1" "$1" "$2" "$3" "$4"
            else
                printf 'zipped-%04d_bend-45_rodrigues_%s.json: bend-45 %s/rodrigues discretization.order=%s solver.residual_tolerance=%s\n' $n "$1" "$1" "$2" "$3"
            fi
        done
    done
    echo "rotbeam sweep: $work/zipped.yaml: 9 runs"
} >"$work/expected-zipped.txt"
"$rotbeam" sweep "$work/zipped.yaml" --list >"$work/zipped.txt" 2>&1 || fail "--list of the zipped sweep failed"
diff "$work/expected-zipped.txt" "$work/zipped.txt" >"$work/list-diff.txt" ||
    fail "the zipped sweep's expansion differs: $(head -4 "$work/list-diff.txt")"
printf 'name: every-combination\ncases: cantilever-moment\n' >"$work/default.yaml"
"$rotbeam" sweep "$work/default.yaml" --list >"$work/default.txt" 2>&1 || fail "--list of the default sweep failed"
for f in displacement mixed; do
    for r in quaternion wiener-milenkovic rodrigues rotation-vector euler-angles; do
        grep -q "^every-combination-[0-9]*_cantilever-moment_${r}_$f.json: cantilever-moment $f/$r\$" "$work/default.txt" ||
            fail "the default sweep lacks $f/$r"
    done
done
grep -q ": 10 runs\$" "$work/default.txt" || fail "the default sweep: $(tail -1 "$work/default.txt")"

# One run of the sweep.
"$rotbeam" sweep "$file" --jobs 2 --out "$work/one" >/dev/null 2>"$work/err.txt" ||
    fail "the sweep failed: $(tail -1 "$work/err.txt")"
complete_files "$work/one" "the sweep's output"
for f in sweep.csv index.md index.html; do
    [ -s "$work/one/$f" ] || fail "the sweep wrote no $f"
done
head -1 "$work/one/sweep.csv" | grep -q '^run,case,formulation,rotation,analysis.load_factors,members.\*.elements,status,step,value,point,u1,u2,u3,angle,' ||
    fail "sweep.csv header: $(head -1 "$work/one/sweep.csv")"
# One load step per run, two named points (root, tip): 48 rows.
[ "$(($(wc -l <"$work/one/sweep.csv") - 1))" -eq 48 ] ||
    fail "sweep.csv has $(($(wc -l <"$work/one/sweep.csv") - 1)) rows, expected 24 runs × 2 points"
grep -q '^rollup-load-elements-0012_cantilever-moment_quaternion_displacement,cantilever-moment,displacement,quaternion,2.0,8,[a-z-]*,load_factor,2.0,tip,' "$work/one/sweep.csv" ||
    fail "sweep.csv has no row for run 12 (λ = 2, 8 elements) at the tip"

# Each result is the one `rotbeam run --set` makes.
mkdir -p "$work/individual/runs" "$work/swept/runs"
while read -r name rest; do
    name=${name%:}
    [ "$name" = rotbeam ] && continue
    read -r case combination k1 k2 <<<"$rest"
    "$rotbeam" run "$case" --formulation "${combination%/*}" --rotation "${combination#*/}" \
        --set "$k1" --set "$k2" --json "$work/individual/runs/$name" >/dev/null 2>&1 ||
        fail "rotbeam run for $name failed"
done <"$work/list.txt"
rm -f "$work/individual/runs/"*.csv  # `run --json` writes its load steps beside; the suite does not
python3 - "$work/one/runs" "$work/swept/runs" <<'PY'
import json, pathlib, sys
for p in pathlib.Path(sys.argv[1]).glob("*.json"):
    j = json.loads(p.read_text())
    j.pop("input_key")
    (pathlib.Path(sys.argv[2]) / p.name).write_text(json.dumps(j))
PY
same "$work/individual" "$work/swept" "the sweep's runs against rotbeam run --set"

# A rerun makes nothing again.
touch -d '2000-01-01' "$work/one/runs/"*.json
"$rotbeam" sweep "$file" --jobs 2 --out "$work/one" >/dev/null 2>&1 || fail "the rerun failed"
[ -z "$(find "$work/one/runs" -newermt '2001-01-01' -name '*.json')" ] ||
    fail "the rerun made runs again"

# Three shards merged equal one run.
for i in 1 2 3; do
    "$rotbeam" sweep "$file" --jobs 1 --shard $i/3 --out "$work/s$i" >/dev/null 2>"$work/err$i.txt" ||
        fail "shard $i/3 failed: $(tail -1 "$work/err$i.txt")"
done
"$rotbeam" merge "$work/s1" "$work/s2" "$work/s3" --out "$work/merged" >/dev/null 2>"$work/err.txt" ||
    fail "merge failed: $(tail -1 "$work/err.txt")"
same "$work/one" "$work/merged" "three shards of the sweep merged"
cmp -s "$work/one/sweep.csv" "$work/merged/sweep.csv" || fail "the merged sweep.csv differs"
"$rotbeam" merge "$work/s1" "$work/s3" --out "$work/partial" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 5 ] || fail "merge without shard 2: exit $code, expected 5"
grep -q -- "rotbeam sweep $file --shard 2/3" "$work/err.txt" ||
    fail "merge without shard 2 names no sweep command: $(tail -1 "$work/err.txt")"

# The sweep file changed (a comment added) or gone between the shards and the merge: refused on one
# line naming it, exit 2, nothing written (the shards' manifests point to a copy of the file).
cp "$file" "$work/copy.yaml"
for i in 1 2 3; do
    mkdir -p "$work/c$i" && cp -r "$work/s$i/." "$work/c$i/"
    python3 - "$work/c$i/shard.json" "$work/copy.yaml" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["job"]["sweep"] = sys.argv[2]
json.dump(m, open(sys.argv[1], "w"))
PY
done
echo "# changed" >>"$work/copy.yaml"
for what in changed gone; do
    [ $what = gone ] && rm "$work/copy.yaml"
    "$rotbeam" merge "$work/c1" "$work/c2" "$work/c3" --out "$work/m-$what" >/dev/null 2>"$work/err.txt"
    code=$?
    [ $code -eq 2 ] || fail "merge with the sweep file $what: exit $code, expected 2"
    [ "$(wc -l <"$work/err.txt")" -eq 1 ] && grep -qF "rotbeam merge: $work/copy.yaml: $what" "$work/err.txt" ||
        fail "merge with the sweep file $what: '$(cat "$work/err.txt")'"
    [ -e "$work/m-$what" ] && fail "merge with the sweep file $what wrote its output"
done

# Bad sweep files: exit 2, one line starting with the file and holding the expected fragment.
bad=$src/cases/bad-sweeps
listed=0
while IFS='|' read -r name fragment; do
    case $name in '#'* | '') continue ;; esac
    name=${name% }
    fragment=${fragment# }
    listed=$((listed + 1))
    for mode in --list run; do
        args=(sweep "$bad/$name" --out "$work/bad")
        [ $mode = --list ] && args+=(--list)
        "$rotbeam" "${args[@]}" >"$work/out.txt" 2>"$work/err.txt"
        code=$?
        [ $code -eq 2 ] || fail "$name ($mode): exit $code, expected 2"
        [ "$(wc -l <"$work/err.txt")" -eq 1 ] || fail "$name ($mode): not one line: $(cat "$work/err.txt")"
        grep -qF -- "$bad/$name$fragment" "$work/err.txt" ||
            fail "$name ($mode): '$(cat "$work/err.txt")' lacks '$bad/$name$fragment'"
        [ -s "$work/out.txt" ] && fail "$name ($mode): printed $(head -1 "$work/out.txt")"
        [ -e "$work/bad" ] && fail "$name ($mode): wrote $work/bad"
    done
done <"$bad/expected.txt"
[ "$listed" -eq "$(ls "$bad"/*.yaml | wc -l)" ] ||
    fail "cases/bad-sweeps/expected.txt lists $listed files, the folder has $(ls "$bad"/*.yaml | wc -l)"

[ $failures -eq 0 ] && echo "sweep: all checks passed"
exit $((failures > 0))
