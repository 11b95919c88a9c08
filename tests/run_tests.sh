#!/usr/bin/env bash
# The whole test suite: installs what is missing, then
#   1. builds build/ (Release) and runs every test with CTest;
#   2. builds build-sanitize/ and runs the suite under ASan + UBSan (tests/run_sanitized.sh);
#   3. fuzzes every reader for TOWGEOM_FUZZ_SECONDS per target (default 60) with
#      tests/fuzz/run_fuzzers.sh. TOWGEOM_FUZZ_SECONDS=0 is the one way to skip it: clang's
#      libFuzzer is in the package list installed above, so without it the run fails.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/cmake/ensure_packages.sh"
bash "$root/cmake/build.sh" -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
bash "$root/tests/run_sanitized.sh"

seconds=${TOWGEOM_FUZZ_SECONDS:-60}
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' >"$probe/f.cpp"
if ((seconds == 0)); then
  echo "towgeom: fuzzing skipped (TOWGEOM_FUZZ_SECONDS=0)" >&2
elif command -v clang++ >/dev/null && clang++ -fsanitize=fuzzer "$probe/f.cpp" -o "$probe/f" 2>/dev/null; then
  bash "$root/tests/fuzz/run_fuzzers.sh" "$seconds"
else
  echo "towgeom: FAILED: no clang++ with libFuzzer, the fuzzing stage cannot run (cmake/ensure_packages.sh" \
    "installs clang and libclang-rt-14-dev; TOWGEOM_FUZZ_SECONDS=0 skips the stage on purpose)" >&2
  exit 1
fi
