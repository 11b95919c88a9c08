#!/usr/bin/env bash
# Fuzzes every towgeom reader with libFuzzer (clang; ASan + UBSan, assertions on) for SECONDS
# per target (default 60); the long run is `run_fuzzers.sh 600`.
#
# Builds build-sanitize/ (tests/build_sanitized.sh: clang with ASan, UBSan and the library
# instrumented for libFuzzer; the sanitized tests run from the same build; reused) and runs the targets side by side, TOWGEOM_JOBS at a time (default:
# the number of cores). Each target starts from its committed seeds and regression inputs
# (tests/fuzz/corpus/TARGET, tests/fuzz/regressions/TARGET, read only) and from what earlier runs
# found (build-sanitize/fuzz/TARGET/corpus). A crash, a leak,
# an uncaught exception, an input taking over 10 s or needing over 2 GB fails the run; the input
# that did it is kept in build-sanitize/fuzz/TARGET/artifacts/ and the log in build-sanitize/fuzz/TARGET.log.
# Reproduce with: build-sanitize/tests/fuzz/fuzz_TARGET ARTIFACT
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
seconds=${1:-60}
parallel=${TOWGEOM_JOBS:-$(nproc 2>/dev/null || echo 2)}
targets=(stack_reader stack_fit)
# The fit target takes inputs up to kMaxFitInput = 64 KiB (fuzz_harness.hpp): fuzz up to that size.
declare -A max_len=([stack_reader]=65536 [stack_fit]=65536)

bash "$root/tests/build_sanitized.sh"
build=$root/build-sanitize

fuzz() {
  local target=$1 work=$build/fuzz/$1
  mkdir -p "$work/corpus" "$work/artifacts"
  "$build/tests/fuzz/fuzz_$target" "$work/corpus" "$here/corpus/$target" "$here/regressions/$target" \
    -dict="$here/stw.dict" -max_total_time="$seconds" -max_len="${max_len[$target]}" \
    -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$work/artifacts/" -print_final_stats=1 \
    >"$work.log" 2>&1
}

pids=()
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  fuzz "$target" &
  pids+=($!)
done
failed=0
for i in "${!targets[@]}"; do
  target=${targets[$i]}
  log=$build/fuzz/$target.log
  status=0
  wait "${pids[$i]}" || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if ((status)); then
    failed=1
    echo "run_fuzzers: fuzz_$target FAILED (exit $status) after ${runs:-?} executions; log: $log" >&2
    grep -E "^==[0-9]+== ?ERROR|runtime error|terminate called|what\(\)|towgeom fuzz:|Test unit written" "$log" >&2 || tail -20 "$log" >&2
  else
    echo "run_fuzzers: fuzz_$target: ${runs:-?} executions in ${seconds} s, no crash" >&2
  fi
done
exit "$failed"
