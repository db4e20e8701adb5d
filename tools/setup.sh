#!/usr/bin/env bash
# Installs every Debian package volren needs (idempotent) and configures + builds it.
# Usage: tools/setup.sh [--deps-only] [--target TARGET] [BUILD_DIR]
#   --target volren builds the program and what it loads at run time (plugins, shaders, the
#   default scene's data), no test; without it everything is built.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps_only=0
target=()
if [ "${1:-}" = "--deps-only" ]; then deps_only=1; shift; fi
if [ "${1:-}" = "--target" ]; then target=(--target "$2"); shift 2; fi
build=${1:-"$here/build"}

packages=(
  build-essential cmake pkg-config
  libopenscenegraph-dev openscenegraph
  libglm-dev libtiff-dev libopenimageio-dev openimageio-tools zlib1g-dev
  libgtest-dev libgmock-dev nlohmann-json3-dev libgdcm-dev libgdcm-tools libblosc-dev
  libegl-dev libegl-mesa0 libgl-dev libgl1-mesa-dri libgbm1
  mricron-data
  xvfb xauth netpbm
  libimgui-dev fonts-dejavu-core
  python3-dev python3-numpy pybind11-dev
  python3-zarr
)

# The fuzzers (tests/fuzz, optional) need clang and its libFuzzer runtime: VOLREN_SETUP_FUZZ=1.
[ "${VOLREN_SETUP_FUZZ:-0}" = 1 ] && packages+=(clang libclang-rt-14-dev)
# volren bench's plot and its VTK peer (tools/bench.sh): VOLREN_SETUP_BENCH=1.
[ "${VOLREN_SETUP_BENCH:-0}" = 1 ] && packages+=(gnuplot-nox python3-vtk9 fonts-dejavu-core)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "volren setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
[ $deps_only -eq 1 ] && exit 0

jobs=$(nproc 2>/dev/null || echo 2)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build" -j "$jobs" "${target[@]}"
