#!/usr/bin/env bash
# The whole test suite: installs what is missing, then
#   1. builds build/ (Release) and runs every test with CTest;
#   2. builds build-sanitize/ (clang: ASan + UBSan, the library instrumented for libFuzzer) and
#      runs the suite under the sanitizers (tests/run_sanitized.sh);
#   3. fuzzes every reader for TOWGEOM_FUZZ_SECONDS per target (default 60) with
#      tests/fuzz/run_fuzzers.sh, from the same sanitized build. TOWGEOM_FUZZ_SECONDS=0 is the one
#      way to skip it: clang's libFuzzer is in the package list installed above, so without it the
#      run fails.
# Each stage's wall time is printed as it ends, and all of them at the end.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc 2>/dev/null || echo 2)
stages=()
stage() {  # stage NAME COMMAND...: runs COMMAND, then prints and records its wall time
  local name=$1 start=$SECONDS
  shift
  echo "towgeom: stage '$name' started" >&2
  "$@"
  stages+=("$(printf '%-28s %5d s' "$name" $((SECONDS - start)))")
  echo "towgeom: stage '$name' took $((SECONDS - start)) s" >&2
}
summary() {
  local status=$?
  ((${#stages[@]})) && printf 'towgeom: stage times (total %d s):\n%s\n' "$SECONDS" "$(printf '  %s\n' "${stages[@]}")" >&2
  return $status
}
trap summary EXIT

stage "install packages" bash "$root/cmake/ensure_packages.sh"
# Both builds batch the library's sources (CMAKE_UNITY_BUILD, cmake/towgeomPrecompiled.cmake): about
# 40 % less compile time. The add_subdirectory test still builds them one by one (a source that
# misses an include it needs fails there).
# The Python module is built for Debian's python3 (its numpy, meshio and pytest run the tests),
# whatever other python3 comes first on PATH.
stage "release build" bash "$root/cmake/build.sh" -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON -DCMAKE_UNITY_BUILD=ON \
  -DPython_EXECUTABLE=/usr/bin/python3
stage "release tests" ctest --test-dir "$root/build" --output-on-failure -j "$jobs"
stage "sanitized build" bash "$root/tests/build_sanitized.sh"
stage "sanitized tests" bash "$root/tests/run_sanitized.sh"

seconds=${TOWGEOM_FUZZ_SECONDS:-60}
if ((seconds == 0)); then
  echo "towgeom: fuzzing skipped (TOWGEOM_FUZZ_SECONDS=0)" >&2
else
  stage "fuzzing" bash "$root/tests/fuzz/run_fuzzers.sh" "$seconds"
fi
