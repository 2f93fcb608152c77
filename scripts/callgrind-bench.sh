#!/usr/bin/env bash
# Instruction counts of the bench's cases under callgrind: a measure of the work a change costs or
# saves that, unlike a timing, does not depend on how busy the machine is (a restructuring must keep
# every count within 3 %). Every combination runs the catalog discretization of
#   the roll-up (cantilever-moment: λ to 2 with its substeps), the 45° bend (P to 600),
#   the joined beam's modal analysis, and the first 20 time steps of its dead-load dynamics
# (the cases the bench times; the bench's own search over meshes would multiply the cost by ~50).
# Usage: scripts/callgrind-bench.sh [ROTBEAM] > counts.txt   (default build/release/cases/runner/rotbeam)
#        scripts/callgrind-bench.sh --compare BEFORE.txt AFTER.txt   (exit 1 if any count moved > 3 %)
# Output: one line per run, "<case>/<formulation>/<rotation> <instructions>".
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "${1:-}" = "--compare" ]; then
  join <(sort "$2") <(sort "$3") | awk '
    { change = ($3 - $2) / $2; if (change < 0) a = -change; else a = change
      if (a > worst) { worst = a; where = $1 }
      flag = (a > 0.03) ? "  MOVED" : ""; if (a > 0.03) bad++
      printf "%-55s %14.0f %14.0f %+8.3f%%%s\n", $1, $2, $3, 100 * change, flag }
    END { printf "largest change %.3f%% (%s); %d of %d beyond 3%%\n", 100 * worst, where, bad, NR
          exit (bad > 0) }'
  exit $?
fi

rotbeam=$(realpath "${1:-build/release/cases/runner/rotbeam}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The solve alone: a program that estimates the discretization error by default (companion runs,
# docs/error-estimates.md) is measured with the estimate off, so counts compare with older builds.
no_estimate=()
if "$rotbeam" run --help | grep -q -- '--estimate'; then no_estimate=(--estimate off); fi

count() {  # count NAME ARGS...: the instructions of `rotbeam ARGS... --quiet`
  local name=$1
  shift
  valgrind --tool=callgrind --callgrind-out-file="$work/out" "$rotbeam" "$@" "${no_estimate[@]}" --quiet \
    >/dev/null 2>"$work/log" || { echo "callgrind-bench: $name failed" >&2; cat "$work/log" >&2; exit 1; }
  echo "$name $(sed -n 's/^summary: *//p' "$work/out")"
}

for formulation in displacement mixed; do
  for rotation in $("$rotbeam" list | sed -n '/^parameterizations:/,/^[a-z]/s/^  //p'); do
    c="--formulation $formulation --rotation $rotation"
    # shellcheck disable=SC2086
    count "rollup/$formulation/$rotation" run cases/cantilever-moment.yaml $c
    # shellcheck disable=SC2086
    count "bend-45/$formulation/$rotation" run cases/bend-45.yaml $c
    # shellcheck disable=SC2086
    count "joined-beam-modal/$formulation/$rotation" run cases/joined-beam.yaml $c
    # shellcheck disable=SC2086
    count "joined-beam-dead-20-steps/$formulation/$rotation" run cases/joined-beam-dead.yaml $c \
      --set analysis.end_time=0.02
  done
done
