#!/usr/bin/env bash
# A check of tests/sanitizer/not_sanitized.txt (which select_by_coverage.py writes): which of the library's source files
# the sanitized selection of tests runs. Builds build-coverage/ (g++ -O1 --coverage; reused),
# runs exactly the tests tests/run_sanitized.sh runs (same labels, same exclusions), then prints
# per source file of src/ (library and CLI) the share of its lines executed (gcov) and fails when a file's code
# did not run at all: every source file must still run in at least one sanitized test. Not part
# of the test command (it builds the library once more); run it after changing
# not_sanitized.txt:
#   bash tests/sanitizer/measure_coverage.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build-coverage
bash "$root/cmake/build.sh" --dir build-coverage -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 --coverage" \
  -DCMAKE_EXE_LINKER_FLAGS=--coverage -DCMAKE_SHARED_LINKER_FLAGS=--coverage \
  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
  -DTOWGEOM_BUILD_TESTS=ON -DTOWGEOM_BUILD_BENCHMARKS=ON -DTOWGEOM_BUILD_DOCS=OFF
find "$build" -name '*.gcda' -delete
bash "$root/tests/run_sanitized.sh" --in "$build" || echo "measure_coverage: some tests failed (coverage still reported)" >&2

report=$build/coverage.txt
unrun=0
: >"$report"
while IFS= read -r source; do
  rel=${source#"$root/src/"}
  objects=$build/src/CMakeFiles/towgeom_objects.dir
  if [[ "$rel" == cli/* ]]; then objects=$build/src/CMakeFiles/towgeom_cli.dir; fi
  object=$objects/$rel.o
  summary=$(cd "$(dirname "$object")" && gcov -n -o "$object" "$source" 2>/dev/null |
    grep -A1 -F "File '$source'" | grep '^Lines executed:' || true)
  percent=$(sed -n 's/^Lines executed:\([0-9.]*\)% of \([0-9]*\)$/\1 \2/p' <<<"$summary")
  if [[ -z "$percent" ]]; then percent="0.00 ?"; fi
  printf '%7s%% of %5s lines  %s\n' $percent "$rel" >>"$report"
  if [[ "${percent%% *}" == "0.00" ]]; then unrun=$((unrun + 1)); fi
done < <(find "$root/src" -name '*.cpp' | sort)
sort -n "$report"
if ((unrun)); then
  echo "measure_coverage: $unrun source file(s) of src/ run in no sanitized test" >&2
  exit 1
fi
echo "measure_coverage: every source file of src/ runs in at least one sanitized test ($report)"
