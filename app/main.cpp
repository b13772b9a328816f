/// @file
/// @brief Thin entry point: everything lives in the vdfx_app library so tests can drive it.
///
/// This file alone is compiled for plain x86-64 (app/CMakeLists.txt) so the instruction-set
/// check below can run, and say what is wrong, on a CPU older than the build's floor.
#include <cstdio>
#include <cstdlib>

#include "app/commands.h"

namespace {

// Runs before the other static initialisers (priority 101 is the first one user code may take),
// none of which may then execute an AVX2 instruction on a CPU without it.
__attribute__((constructor(101))) void check_instruction_set() {
#if defined(__x86_64__) && defined(VDFX_NEEDS_AVX2)
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    std::fprintf(stderr,
                 "vdfx: this build needs a CPU with AVX2 and FMA (x86-64-v3: Intel Haswell or AMD "
                 "Zen and newer). Rebuild with `cmake -DVDFX_ARCH=x86-64` to run on this one.\n");
    std::_Exit(3);  // the contract's "internal error": not the user's input
  }
#endif
}

}  // namespace

int main(int argc, char** argv) {
  return vdfx::app::run_main(vdfx::app::Args(argv + 1, argv + argc));
}
