#!/usr/bin/env bash
# The test suite under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer:
# builds build-sanitize/ (tests/build_sanitized.sh: clang, the build the fuzzers use too) and
# runs every test not labelled skip-sanitize and not listed in tests/sanitizer/not_sanitized.txt
# (costly tests whose every line of library code other sanitized tests run, as measured by
# tests/sanitizer/select_by_coverage.py, which writes the list). Sanitizer options come from the
# build (cmake/towgeomSanitize.cmake).
#   run_sanitized.sh             builds build-sanitize/ and runs the selection there
#   run_sanitized.sh --in DIR    runs the same selection in the (built) build directory DIR,
#                                e.g. the coverage build of tests/sanitizer/measure_coverage.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [[ "${1:-}" == "--in" ]]; then
  build=$2
else
  build=$root/build-sanitize
  bash "$root/tests/build_sanitized.sh"
fi

# One anchored alternative per listed name, regex characters escaped; a name that matches no
# test fails the run (a renamed test must not silently come back or drop out of the list).
list=$root/tests/sanitizer/not_sanitized.txt
if [[ ! -r "$list" ]]; then
  echo "towgeom: $list is missing: the sanitizer stage would run tests it is not meant to" >&2
  exit 1
fi
mapfile -t names < <(grep -v -e '^#' -e '^[[:space:]]*$' "$list" || true)
if ((${#names[@]} == 0)); then
  echo "towgeom: $list names no test" >&2
  exit 1
fi
exclude=""
for name in "${names[@]}"; do
  pattern="^$(printf '%s' "$name" | sed 's/[][\.*^$+?(){}|]/\\&/g')\$"
  if ! ctest --test-dir "$build" -N -R "$pattern" | grep -q "Total Tests: 1$"; then
    echo "towgeom: tests/sanitizer/not_sanitized.txt names no test of the build: $name" >&2
    exit 1
  fi
  exclude+="${exclude:+|}$pattern"
done
ctest --test-dir "$build" --output-on-failure -LE skip-sanitize ${exclude:+-E "$exclude"} \
  -j "${TOWGEOM_JOBS:-$(nproc 2>/dev/null || echo 2)}"
