#!/usr/bin/env bash
# Builds build-sanitize/ (reused): the library, CLI, tests, benchmarks and fuzz targets with clang
# under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer, the library's
# objects also instrumented for libFuzzer. One build serves both tests/run_sanitized.sh and
# tests/fuzz/run_fuzzers.sh. Debug at -O1 (assertions on, still quick) with -g1 (line tables: the
# sanitizers' stack traces keep function, file and line, without full debug info).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if ! command -v clang++ >/dev/null; then
  echo "towgeom: clang++ not found: the sanitized build needs clang and libclang-rt-14-dev" \
    "(cmake/ensure_packages.sh installs both)" >&2
  exit 1
fi
bash "$root/cmake/build.sh" --dir build-sanitize -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-g1 -O1" -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
  -DTOWGEOM_SANITIZE=address,undefined -DTOWGEOM_BUILD_FUZZERS=ON \
  -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON -DTOWGEOM_BUILD_DOCS=OFF
