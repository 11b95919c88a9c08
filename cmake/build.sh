#!/usr/bin/env bash
# Configures and builds towgeom, reusing the build directory when it exists.
#   build.sh [--dir DIR] [CMAKE_ARGS...]   DIR relative to the source tree (default: build);
#                                          Release unless CMAKE_ARGS set CMAKE_BUILD_TYPE.
# TOWGEOM_JOBS caps the parallel compile jobs (default: the number of cores).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=build
if [[ "${1:-}" == "--dir" ]]; then
  dir=$2
  shift 2
fi
jobs=${TOWGEOM_JOBS:-$(nproc 2>/dev/null || echo 2)}
cmake -S "$root" -B "$root/$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/$dir" -j "$jobs"
