#!/usr/bin/env bash
# The readers' tests under AddressSanitizer + UndefinedBehaviorSanitizer (issue 11): builds the
# io, effects and xr test binaries and every fuzz target's replay binary with the sanitizers
# (.ci/asan_configure.sh, into build-asan/ or $VDFX_ASAN_BUILD_DIR), then runs those tests: the
# sidecar, recording, input-file, image, output-path and atomic-write tests, the evaluation
# tests, the HID, HMD-profile and recording-replay tests, and each fuzz target over its seed
# corpus and kept crash inputs. Any undefined behaviour, memory error or leak fails the run (leaks
# inside third-party libraries excepted, each in cmake/lsan_suppressions.txt with the reason).
# Bounded on purpose: the GL, ui and app tests are not in it (building all of vdfx sanitized would
# double the CI time); docs/reliability.md says so.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
build=${VDFX_ASAN_BUILD_DIR:-$root/build-asan}
jobs=${VDFX_JOBS:-$(nproc)}
"$root/.ci/asan_configure.sh" "$build"
replays=(sidecar recording hmd_profile hid_descriptor hid_reports)
replays=("${replays[@]/#/fuzz_}")
cmake --build "$build" -j "$jobs" --target vdfx_test_io vdfx_test_effects vdfx_test_xr \
  "${replays[@]/%/_replay}"
cd "$build"
export ASAN_OPTIONS=detect_leaks=1:strict_init_order=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Only third-party libraries' own leaks, each explained in the file.
export LSAN_OPTIONS=suppressions=$root/cmake/lsan_suppressions.txt:print_suppressions=0
if command -v llvm-symbolizer-14 > /dev/null; then
  export ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-14)
fi
exec ctest --output-on-failure -j "$jobs" -L '^(io|effects|xr|fuzz)$' "$@"
