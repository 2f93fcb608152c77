#!/usr/bin/env bash
# clang-tidy's bugprone checks (Debian's clang-tidy) over rotbeam's sources; any finding fails.
# Usage: scripts/tidy.sh [BASE]
#   without BASE: every source file of the release build's compile_commands.json;
#   with BASE (a commit): only the .cpp files changed since BASE, and the .cpp files that include
#   a header changed since BASE (CI; docs/quality-checks.md says why not every file there).
# The checks are bugprone-* less the -bugprone-* exclusions of .clang-tidy (the one place where
# they are chosen, with their reasons; its CheckOptions apply too), so that its style checks
# (naming, performance) stay advice for editors, not a CI gate.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
checks="-*,bugprone-*,$(grep -o -E -- '-bugprone-[a-z-]+' .clang-tidy | paste -sd, -)"
if [ ! -f build/release/compile_commands.json ]; then
  cmake --preset release >/dev/null
fi
# One compile command per source file, also when the tree is a unity build (CI's: a unity source
# stands for several files there): build/release/tidy/compile_commands.json.
python3 scripts/tidy_compile_db.py build/release
db=build/release/tidy

files=()
if [ $# -ge 1 ]; then
  mapfile -t changed < <(git diff --name-only --diff-filter=d "$1" -- \
    'core/*' 'cases/*' 'formulations/*' 'parameterizations/*' 'combinations/*' 'runs/*' \
    'estimates/*' 'studies/*' 'benches/*' 'reports/*' 'tests/*')
  for f in "${changed[@]}"; do
    case "$f" in
      *.cpp) files+=("$root/$f") ;;
      *.hpp) mapfile -t users < <(git grep -l -E "#include \"($f|$(basename "$f"))\"" -- '*.cpp')
             for u in "${users[@]}"; do files+=("$root/$u"); done ;;
    esac
  done
  if [ ${#files[@]} -eq 0 ]; then
    echo "tidy: no C++ source changed since $1"
    exit 0
  fi
  mapfile -t files < <(printf '%s\n' "${files[@]}" | sort -u)
  # Only files the Release build compiles: without their compile command clang-tidy guesses the
  # flags and reports missing definitions. The fuzz targets (tests/fuzz) are built only by the
  # clang trees (asan, fuzz), so they are left out here, by name.
  mapfile -t known < <(python3 -c 'import json
for e in json.load(open("build/release/tidy/compile_commands.json")): print(e["file"])' | sort -u)
  mapfile -t skipped < <(comm -23 <(printf '%s\n' "${files[@]}") <(printf '%s\n' "${known[@]}"))
  mapfile -t files < <(comm -12 <(printf '%s\n' "${files[@]}") <(printf '%s\n' "${known[@]}"))
  for f in "${skipped[@]}"; do echo "tidy: not in the Release build, left out: ${f#"$root"/}"; done
  if [ ${#files[@]} -eq 0 ]; then
    echo "tidy: no C++ source of the Release build changed since $1"
    exit 0
  fi
else
  mapfile -t files < <(python3 -c 'import json,sys
for e in json.load(open("build/release/tidy/compile_commands.json")): print(e["file"])' | sort -u)
fi

echo "tidy: ${#files[@]} files, checks $checks"
start=$(date +%s)
# clang-tidy itself, one process per file, nproc at a time (Debian 12's run-clang-tidy has no
# -warnings-as-errors); --warnings-as-errors makes a finding fail it, and xargs then exits 123.
set +e
printf '%s\n' "${files[@]}" |
  xargs -P "$(nproc)" -n 1 clang-tidy -p "$db" --quiet -checks="$checks" \
    --warnings-as-errors='*' \
    --header-filter="^$root/(core|parameterizations|formulations|combinations|cases|estimates|runs|studies|benches|reports|tests)/" 2>&1 |
  grep -v -E '^[0-9]+ warnings? (and [0-9]+ errors? )?generated\.$|^Suppressed [0-9]+ warnings|^Use -header-filter'
status=${PIPESTATUS[1]}
set -e
echo "tidy: ${#files[@]} files in $(( $(date +%s) - start )) s, exit $status"
exit "$status"
