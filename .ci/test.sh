#!/usr/bin/env bash
# The README's test command: installs what is missing, builds (as the main job does: warnings are
# errors in both, so after the main job nothing is compiled again), and runs
# the whole suite (unit, GL and replay tests) under Xvfb with Mesa's llvmpipe.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
# Formatting first: seconds, and a mis-formatted file fails before the long build.
if git -C "$root" rev-parse --git-dir > /dev/null 2>&1; then "$root/.ci/format.sh"; fi
"$root/.ci/build.sh"
build=${VDFX_BUILD_DIR:-$root/build}
cd "$build"
# GL tests need a display; they are never skipped silently: without one they fail.
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe  # the same renderer on any machine
exec "$root/.ci/with_display.sh" ctest --output-on-failure -j "${VDFX_JOBS:-$(nproc)}" "$@"
