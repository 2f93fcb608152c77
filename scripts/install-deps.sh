#!/usr/bin/env bash
# Installs the Debian packages rotbeam needs, and nothing when they are all present.
# clang-14, libclang-rt-14-dev (libFuzzer and the sanitizer runtimes) and llvm-14 (llvm-cov) are for
# the fuzz preset (docs/fuzzing.md). libcmark-gfm-dev and libcmark-gfm-extensions-dev convert the
# report's Markdown to HTML; chromium and python3-websockets run the report's browser test
# (tests/reports/browser_check.py); python3-meshio reads the ParaView files back in a test;
# openmpi-bin and libopenmpi-dev give the build its second program, rotbeam-mpi (mpirun -np N
# rotbeam-mpi suite, docs/distributed-runs.md); ccache is CI's compiler cache kept between runs (.ci/run).
# Idempotent: `apt-get update` runs only when something must be installed.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libgsl-dev libsundials-dev libsuitesparse-dev
  libboost-test-dev libyaml-cpp-dev nlohmann-json3-dev libspectra-dev
  gnuplot-nox clang-tidy python3-meshio
  libcmark-gfm-dev libcmark-gfm-extensions-dev
  chromium python3-websockets
  clang-14 libclang-rt-14-dev llvm-14 ccache
  openmpi-bin libopenmpi-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
