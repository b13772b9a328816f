#!/usr/bin/env bash
# Configures the one sanitizer build that .ci/sanitize.sh and .ci/fuzz.sh share (issue 11):
# clang-14, AddressSanitizer + UndefinedBehaviorSanitizer, libFuzzer coverage (-DVDFX_FUZZ=ON),
# no GL and no benchmarks, warnings as errors, into $1. One build for both keeps the CI time
# bounded: the sanitized libraries are compiled once.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
  -DCMAKE_CXX_COMPILER=clang++-14 -DVDFX_FUZZ=ON -DVDFX_WITH_GL=OFF -DVDFX_BUILD_BENCH=OFF \
  -DVDFX_WERROR=ON >/dev/null
