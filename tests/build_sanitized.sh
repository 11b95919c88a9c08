#!/usr/bin/env bash
# Builds build-sanitize/ (reused) with clang: the library, CLI and fuzz harnesses instrumented
# for AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer, the library's objects
# also for libFuzzer; the tests and benchmarks linked with the sanitizers' runtime, their own
# code not instrumented (cmake/towgeomSanitize.cmake says why). One build serves both tests/run_sanitized.sh and
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
  -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON -DTOWGEOM_BUILD_DOCS=OFF -DTOWGEOM_BUILD_PYTHON=OFF -DCMAKE_UNITY_BUILD=ON
