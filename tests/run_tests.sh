#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, and runs every test with CTest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/cmake/ensure_packages.sh"
bash "$root/cmake/build.sh" -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
