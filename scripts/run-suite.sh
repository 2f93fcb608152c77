#!/usr/bin/env bash
# Install what is missing, build rotbeam in Release and run the main job: the benchmark suite with
# its report (out/index.md, out/index.html). Extra arguments go to `rotbeam suite`.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target rotbeam
./build/release/cases/runner/rotbeam suite --out out "$@"
