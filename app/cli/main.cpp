/// @file
/// @brief The `vdfx` executable: the light commands, and the media module for the others.
///
/// Start-up: the executable links only the light commands (validate, eval, hmd, devices: no
/// video, image or GL library), so the dynamic loader resolves a few dozen libraries, not the
/// ~250 that FFmpeg, OpenCV's image codecs and GL pull in. Every other command runs from the
/// media module libvdfx_media.so beside the executable, loaded here on demand
/// (docs/architecture.md, "Start-up").
///
/// This file alone is compiled for plain x86-64 (app/cli/CMakeLists.txt) so the instruction-set
/// check below can run, and say what is wrong, on a CPU older than the build's floor.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "app/cli/command_registry.h"

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

namespace {

/// The media module's path: beside this executable (resolved through /proc/self/exe, so a
/// symlink to vdfx works too).
std::filesystem::path module_path() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (ec ? std::filesystem::path(".") : exe.parent_path()) / "libvdfx_media.so";
}

int run_media_module(const char* command, int argc, char** argv) {
  const std::string path = module_path().string();
  // Lazy binding: only the functions the command calls are resolved.
  void* module = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!module) {
    std::cerr << "vdfx " << command << ": internal error: cannot load the media module " << path
              << " (" << dlerror() << "); it must sit beside the vdfx executable\n";
    return vdfx::app::kExitInternal;
  }
  using Entry = int (*)(int, char**);
  const auto entry = reinterpret_cast<Entry>(dlsym(module, "vdfx_media_main"));
  if (!entry) {
    std::cerr << "vdfx " << command << ": internal error: " << path << " has no vdfx_media_main\n";
    return vdfx::app::kExitInternal;
  }
  const int code = entry(argc - 1, argv + 1);
  std::cout.flush();
  // No dlclose: static objects of the module may still be referenced by exit handlers.
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vdfx::app;
  return dispatch(Args(argv + 1, argv + argc), [&](const Command& c, const Args& rest) {
    if (c.home == CommandHome::kLight) {
      const int code = run_guarded(c.name, c.light_run, rest);
      if (code != kExitRunInMediaModule) return code;
    }
    return run_media_module(c.name, argc, argv);
  });
}
