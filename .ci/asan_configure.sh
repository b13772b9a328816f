#!/usr/bin/env bash
# Configures the one sanitizer build that .ci/sanitize.sh and .ci/fuzz.sh share:
# clang-14, AddressSanitizer + UndefinedBehaviorSanitizer, libFuzzer coverage (-DVDFX_FUZZ=ON),
# the whole of vdfx with GL and its tests but no benchmarks and no WebAssembly module (the
# regular build tests it), warnings as errors, into $1. One build for both keeps the CI time
# bounded: every library is compiled once. -O1 with line tables only
# (ASan's own advice): readable stacks, and about a third less compile time than -O2 -g.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
  -DCMAKE_CXX_COMPILER=clang++-14 -DVDFX_FUZZ=ON -DVDFX_BUILD_BENCH=OFF -DVDFX_BUILD_WASM=OFF \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
  -DVDFX_WERROR=ON >/dev/null
