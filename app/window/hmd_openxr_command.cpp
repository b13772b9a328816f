/// @file
/// @brief `vdfx hmd openxr`: the active runtime, its headset, views, refresh rate, swapchain
/// formats and the controller profiles it accepts.
#include "app/window/hmd_openxr_command.h"

#include <iostream>

#include "xr/openxr/gl/openxr_runtime.h"

namespace vdfx::app {

int cmd_hmd_openxr(const Args& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << "usage: vdfx hmd openxr\n\nPrints what the active OpenXR runtime offers: runtime "
                 "name and version, the headset, its views and recommended sizes, refresh rate, "
                 "swapchain formats (and the one vdfx renders to), the controller profiles it "
                 "accepts. The first thing to run on a new headset; quote it in a bug report. "
                 "The runtime is the one the loader finds (XR_RUNTIME_JSON, else "
                 "active_runtime.json; docs/openxr.md).\n";
    return kExitOk;
  }
  if (!args.empty()) {
    std::cerr << "vdfx hmd openxr: takes no arguments (got '" << args[0] << "')\n";
    return kExitUsage;
  }
  std::cout << xr::openxr_report();
  return kExitOk;
}

}  // namespace vdfx::app
