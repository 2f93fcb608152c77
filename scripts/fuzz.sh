#!/usr/bin/env bash
# Build the libFuzzer targets (preset fuzz: clang, ASan + UBSan) and run one of them.
# Usage: scripts/fuzz.sh TARGET SECONDS [libFuzzer options...]
#   TARGET: fuzz_case_loader | fuzz_beamdyn_import | fuzz_command_line | fuzz_shard_manifest |
#           fuzz_sweep_file | fuzz_run_file (docs/fuzzing.md)
# New inputs go to build/fuzz/corpus-TARGET (the committed corpus tests/fuzz/corpus/TARGET is read
# only); a crashing input is written to build/fuzz/TARGET-crash-* and the run stops with status 1.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 2 ]; then
  sed -n '3,5p' "$0" | sed 's/^# //'
  exit 2
fi
target=$1
seconds=$2
shift 2
case "$target" in
  fuzz_case_loader | fuzz_beamdyn_import | fuzz_command_line | fuzz_shard_manifest | fuzz_sweep_file | fuzz_run_file) ;;
  *) echo "fuzz.sh: unknown target '$target' (fuzz_case_loader | fuzz_beamdyn_import | fuzz_command_line | fuzz_shard_manifest | fuzz_sweep_file | fuzz_run_file)" >&2; exit 2 ;;
esac
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j 2 --target "$target"
scratch=build/fuzz/corpus-$target
mkdir -p "$scratch"
exec "build/fuzz/tests/fuzz/$target" -max_total_time="$seconds" -print_final_stats=1 \
  -dict="tests/fuzz/$target.dict" -artifact_prefix="build/fuzz/$target-" "$@" \
  "$scratch" "tests/fuzz/corpus/$target"
