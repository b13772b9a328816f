#!/usr/bin/env bash
# Tests under AddressSanitizer + UndefinedBehaviorSanitizer, in one clang-14 build shared with
# .ci/fuzz.sh (.ci/asan_configure.sh, into build-asan/ or $VDFX_ASAN_BUILD_DIR).
#
# CI's run (the default): the suites of the code that reads and writes files and holds the
# numbers: effects (interpolation, anchors, the CPU references), io (every reader and writer,
# atomic saves, locks, full disks), ui, xr/input (recordings, HID reports), xr/headset and the
# OpenXR backend's GL-free logic, and the fuzz targets' regression inputs. Only their test
# binaries are built, so CI neither compiles nor runs the GL, command and editor tests twice:
# sanitized, they took about 40 minutes of a CI run that must stay under 50
# (docs/reliability.md, "Sanitizers and fuzzing" and "CI time").
#
# VDFX_SANITIZE_ALL=1: the whole suite sanitized (every target, every test but the few long ones
# .ci/sanitize_leaves.txt leaves to the plain run, with why): the GL tests under Xvfb with Mesa's
# llvmpipe as .ci/test.sh does, and the command tests through the sanitized vdfx executable. Run
# it after changing the editor, a command or the GL path.
#
# Any undefined behaviour, memory error or leak fails the run; leaks inside third-party libraries
# are excepted, each in cmake/lsan_suppressions.txt with the reason (the GL driver needs none:
# cmake/sanitize_keep_modules.c).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
build=${VDFX_ASAN_BUILD_DIR:-$root/build-asan}
jobs=${VDFX_JOBS:-$(nproc)}
"$root/.ci/asan_configure.sh" "$build"
labels='^(effects|io|ui|xr_input|xr_headset|xr_openxr|fuzz)$'
if [ "${VDFX_SANITIZE_ALL:-0}" = 1 ]; then
  cmake --build "$build" -j "$jobs"
else
  targets=(vdfx_test_effects vdfx_test_io vdfx_test_ui vdfx_test_xr_input vdfx_test_xr_headset
    vdfx_test_xr_openxr)
  for f in sidecar recording hmd_profile hid_descriptor hid_reports; do
    targets+=("fuzz_${f}_replay")
  done
  cmake --build "$build" -j "$jobs" --target "${targets[@]}"
fi
cd "$build"
export ASAN_OPTIONS=detect_leaks=1:strict_init_order=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Only third-party libraries' own leaks, each explained in the file.
export LSAN_OPTIONS=suppressions=$root/cmake/lsan_suppressions.txt:print_suppressions=0
if command -v llvm-symbolizer-14 > /dev/null; then
  export ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-14)
fi
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
if [ "${VDFX_SANITIZE_ALL:-0}" = 1 ]; then
  # The tests left to the plain run, said in the log (.ci/sanitize_leaves.txt gives the reasons).
  leaves=$(grep -v '^#' "$root/.ci/sanitize_leaves.txt" | grep -v '^$' | paste -sd'|')
  echo "vdfx sanitize: the whole suite; left to the plain run (.ci/sanitize_leaves.txt): $leaves"
  exec "$root/.ci/with_display.sh" ctest --output-on-failure -j "$jobs" -E "$leaves" "$@"
fi
echo "vdfx sanitize: the suites labelled $labels (VDFX_SANITIZE_ALL=1: the whole suite)"
exec "$root/.ci/with_display.sh" ctest --output-on-failure -j "$jobs" -L "$labels" "$@"
