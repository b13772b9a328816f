#!/usr/bin/env bash
# Configures and builds vdfx into build/ (or $VDFX_BUILD_DIR). Extra arguments go to cmake.
# Warnings are errors for both README commands (the main job and the tests): one compile line, so
# running one after the other compiles each file once (VDFX_WERROR=OFF in the environment turns
# it off, for a compiler newer than the one the code is checked with).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${VDFX_BUILD_DIR:-$root/build}
jobs=${VDFX_JOBS:-$(nproc)}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${VDFX_BUILD_TYPE:-RelWithDebInfo} \
  -DVDFX_WERROR=${VDFX_WERROR:-ON} "$@" >/dev/null
cmake --build "$build" -j "$jobs"
