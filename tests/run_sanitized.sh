#!/usr/bin/env bash
# The test suite under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer:
# builds build-sanitize/ (Debug at -O1: assertions on, still quick; reused) and runs every test
# not labelled skip-sanitize. Sanitizer options come from the build (cmake/towgeomSanitize.cmake).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/cmake/build.sh" --dir build-sanitize -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1" \
  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE -DTOWGEOM_SANITIZE=address,undefined \
  -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON -DTOWGEOM_BUILD_DOCS=OFF
ctest --test-dir "$root/build-sanitize" --output-on-failure -LE skip-sanitize -j "${TOWGEOM_JOBS:-$(nproc 2>/dev/null || echo 2)}"
