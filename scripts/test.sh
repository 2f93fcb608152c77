#!/usr/bin/env bash
# Install what is missing, build rotbeam in Release and run every test (unit, verification and the
# published-tolerance gate). Usage: scripts/test.sh [extra ctest arguments, e.g. -L unit]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
start=$SECONDS
cmake --build --preset release -j "$(nproc)"
echo "test.sh: build done in $((SECONDS - start)) s"
ctest --preset release -j "$(nproc)" "$@"
