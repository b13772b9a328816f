#!/usr/bin/env bash
# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer: builds all of
# vdfx, its tests and every fuzz target's replay binary with the sanitizers (.ci/asan_configure.sh,
# into build-asan/ or $VDFX_ASAN_BUILD_DIR), then runs every ctest test, the GL ones under Xvfb
# with Mesa's llvmpipe as .ci/test.sh does, and the command tests through the sanitized vdfx
# executable. Any undefined behaviour, memory error or leak fails the run; leaks inside
# third-party libraries are excepted, each in cmake/lsan_suppressions.txt with the reason (the GL
# driver needs none: cmake/sanitize_keep_modules.c).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
build=${VDFX_ASAN_BUILD_DIR:-$root/build-asan}
jobs=${VDFX_JOBS:-$(nproc)}
"$root/.ci/asan_configure.sh" "$build"
cmake --build "$build" -j "$jobs"
cd "$build"
export ASAN_OPTIONS=detect_leaks=1:strict_init_order=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Only third-party libraries' own leaks, each explained in the file.
export LSAN_OPTIONS=suppressions=$root/cmake/lsan_suppressions.txt:print_suppressions=0
if command -v llvm-symbolizer-14 > /dev/null; then
  export ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-14)
fi
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
exec "$root/.ci/with_display.sh" ctest --output-on-failure -j "$jobs" "$@"
