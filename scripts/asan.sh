#!/usr/bin/env bash
# rotbeam under AddressSanitizer + UndefinedBehaviorSanitizer (the asan preset: clang-14, -O2 -g1,
# assertions on, -fno-sanitize-recover). Every finding stops the process with a report on stderr;
# this script fails on a non-zero ctest, on a sanitizer report in any program's stderr, and on an
# exit code the command does not document.
# Usage: scripts/asan.sh [--full]
#   default (CI): the unit tests (ctest -L unit, the scripted ones included) but the seven whose
#                 build costs most (`heavy` below), the runs of `rotbeam suite --quick`, every
#                 command's --help, every bad-case fixture through `check` and `run` and every
#                 damaged shard manifest through `merge`;
#   --full:       also those seven, every other ctest test (but the label `long`, which the asan test
#                 preset leaves out), the quick suite's studies and every study path (slow: docs/quality-checks.md).
set -euo pipefail
cd "$(dirname "$0")/.."
full=0
if [ "${1:-}" = "--full" ]; then full=1; fi

export ASAN_OPTIONS=halt_on_error=1:abort_on_error=0:detect_leaks=1:strict_string_checks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

heavy='^(test_parameterizations|test_displacement|test_mixed_dynamics|test_mixed_unit|test_displacement_dynamics_jacobian|test_modal_checks|test_harness)$'
cmake --preset asan >/dev/null
build_start=$SECONDS
if [ $full -eq 1 ]; then
  cmake --build --preset asan -j "$(nproc)"
else
  # The unit tests' executables (a test run by a shell script drives the program itself), but the
  # seven tests of the formulations' and parameterizations' kernels (the six, and the harness of
  # their tangents, Jacobians and objectivity): a third of the sanitized build between them, and
  # their code runs sanitized in `suite --quick` (every formulation × parameterization); --full
  # runs them (docs/quality-checks.md, Time).
  mapfile -t unit < <(ctest --preset asan -N -L unit -E "$heavy" 2>/dev/null |
    sed -n 's/^ *Test *#[0-9]*: //p' |
    while read -r t; do ninja -C build/asan -t query "$t" >/dev/null 2>&1 && echo "$t"; done)
  # rotbeam_completion: the generated bash completion, which test_cli_conventions checks and
  # test_install_consumer installs.
  cmake --build --preset asan -j "$(nproc)" --target rotbeam rotbeam_completion "${unit[@]}"
fi
echo "asan: build done in $((SECONDS - build_start)) s"

step() { echo "asan: $1 ($(( $(date +%s) - t0 )) s so far)"; }
t0=$(date +%s)
log=$(mktemp -d)
trap 'rm -rf "$log"' EXIT
rotbeam=build/asan/cases/runner/rotbeam

# expect CODES... -- COMMAND...: run COMMAND, fail on a sanitizer report or an exit code not in CODES.
expect() {
  local codes=() code
  while [ "$1" != "--" ]; do codes+=("$1"); shift; done
  shift
  set +e
  "$@" >"$log/out" 2>"$log/err"
  code=$?
  set -e
  if grep -q -E 'Sanitizer|runtime error:' "$log/err"; then
    echo "asan: FINDING in: $*"
    cat "$log/err"
    exit 1
  fi
  if [[ " ${codes[*]} " != *" $code "* ]]; then
    echo "asan: exit $code (expected ${codes[*]}) from: $*"
    tail -5 "$log/err"
    exit 1
  fi
}

if [ $full -eq 1 ]; then
  ctest --preset asan -j "$(nproc)"
else
  ctest --preset asan -j "$(nproc)" -L unit -E "$heavy"
fi
step "ctest"

# Every command that `rotbeam --help` lists (a new command is covered without editing this file).
expect 0 -- "$rotbeam" --help
commands=$(sed -n '/^commands:/,$p' "$log/out" | awk 'NF && $1 != "commands:" { print $1 }')
[ "$(wc -w <<<"$commands")" -ge 10 ] || { echo "asan: no commands in rotbeam --help"; exit 1; }
for c in $commands; do
  expect 0 -- "$rotbeam" "$c" --help
done
step "every --help"

for f in cases/bad/*.yaml; do
  expect 2 -- "$rotbeam" check "$f"
  expect 2 -- "$rotbeam" run "$f" --quiet
done
step "cases/bad through check and run"

# The damaged shard manifests (the seeds of fuzz_shard_manifest) through `merge`, each as the
# shard.json of a folder of its own.
for f in tests/fuzz/corpus/fuzz_shard_manifest/damaged-*.json; do
  mkdir -p "$log/shard"
  cp "$f" "$log/shard/shard.json"
  expect 2 -- "$rotbeam" merge "$log/shard" --out "$log/merged"
done
step "damaged shard manifests through merge"

# The quick suite's runs; its studies only with --full: sanitized they take more than 8 minutes
# on 2 cores (the joined-beam modal and manufactured-time studies alone), the runs 50 s.
if [ $full -eq 1 ]; then
  expect 0 -- "$rotbeam" suite --quick --out "$log/suite" --jobs "$(nproc)"
  step "suite --quick"
else
  expect 0 -- "$rotbeam" suite --quick --no-studies --out "$log/suite" --jobs "$(nproc)"
  step "suite --quick --no-studies"
fi

if [ $full -eq 1 ]; then
  # Every study of the registry, named by rotbeam's own refusal of an unknown study (as
  # tests/runner/study_interrupt.sh reads them), so that a new study is covered here too.
  expect 2 -- "$rotbeam" study no-such-study
  studies=$(sed -n 's/.*(available: \(.*\), all)$/\1/p' "$log/err" | tr -d ',')
  [ "$(wc -w <<<"$studies")" -ge 10 ] || { echo "asan: no study names in rotbeam's refusal"; exit 1; }
  expect 0 -- "$rotbeam" study rotations --json "$log/rotations.json"
  step "study rotations"
  for s in $studies; do
    [ "$s" != rotations ] || continue
    expect 0 -- "$rotbeam" study "$s" --quick --out "$log/study-$s"
    step "study $s --quick"
  done
fi
echo "asan: no finding"
