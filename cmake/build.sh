#!/usr/bin/env bash
# Configures and builds towgeom, reusing the build directory when it exists.
#   build.sh [--dir DIR] [CMAKE_ARGS...]   DIR relative to the source tree (default: build);
#                                          Release unless CMAKE_ARGS set CMAKE_BUILD_TYPE.
# A new build directory uses Ninja when it is installed (cmake/debian-packages.txt lists
# ninja-build): it schedules the compile jobs of every target together, where make builds the
# targets one after another. An existing directory keeps the generator it was made with.
# TOWGEOM_JOBS caps the parallel compile jobs (default: the number of cores).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=build
if [[ "${1:-}" == "--dir" ]]; then
  dir=$2
  shift 2
fi
jobs=${TOWGEOM_JOBS:-$(nproc 2>/dev/null || echo 2)}
generator=()
if [[ ! -f "$root/$dir/CMakeCache.txt" ]] && command -v ninja >/dev/null; then
  generator=(-G Ninja)
fi
cmake -S "$root" -B "$root/$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/$dir" -j "$jobs"
