#!/usr/bin/env bash
# Runs every libFuzzer target of tests/fuzz for a bounded time: builds them in the
# sanitizer build (.ci/asan_configure.sh, build-asan/ or $VDFX_ASAN_BUILD_DIR, shared with
# .ci/sanitize.sh), then fuzzes each for $VDFX_FUZZ_SECONDS (default 60, as the issue asks: a bounded run in CI that
# finds shallow faults in new reader code; run it longer by hand after changing a reader)
# starting from a copy of its seed corpus, $VDFX_JOBS at a time. A crash, leak, timeout or
# property failure fails the run; the input that caused it is in build-asan/artifacts/NAME/.
# Keep it: copy it to tests/fuzz/regressions/NAME/, fix the bug, and ctest runs it from then on.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
build=${VDFX_ASAN_BUILD_DIR:-$root/build-asan}
seconds=${VDFX_FUZZ_SECONDS:-60}
jobs=${VDFX_JOBS:-$(nproc)}
targets=(sidecar recording hmd_profile hid_descriptor hid_reports)
"$root/.ci/asan_configure.sh" "$build"
cmake --build "$build" -j "$jobs" --target "${targets[@]/#/fuzz_}"
if command -v llvm-symbolizer-14 > /dev/null; then
  export ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-14)
fi
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
run_one() {
  local name=$1 work=$build/fuzz-work/$1 art=$build/artifacts/$1/
  rm -rf "$work" && mkdir -p "$work" "$art"
  cp "$root/tests/fuzz/corpus/$name/"* "$work/"
  local regressions=()
  [ -d "$root/tests/fuzz/regressions/$name" ] && regressions=("$root/tests/fuzz/regressions/$name")
  # -rss_limit_mb/-malloc_limit_mb: an input that makes a reader allocate without bound is a
  # failure too. -timeout: one input may take at most 10 s (a hang).
  if "$build/tests/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=1024 -max_len=16384 -print_final_stats=1 -artifact_prefix="$art" \
      "$work" "${regressions[@]}" > "$build/fuzz-$name.log" 2>&1; then
    echo "fuzz_$name: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz-$name.log" | grep -o '[0-9]*$') inputs in ${seconds} s, no failure"
  else
    echo "fuzz_$name: FAILED (input kept in $art):"
    tail -40 "$build/fuzz-$name.log"
    return 1
  fi
}
export -f run_one
export root build seconds
printf '%s\n' "${targets[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one {}'
