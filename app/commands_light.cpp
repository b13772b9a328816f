/// @file
/// @brief The commands the `vdfx` executable runs itself: they need no video, image or GL
/// library, so linking only these keeps those libraries out of its start-up.
#include "app/commands.h"

namespace vdfx::app {

CommandFn light_command(const std::string& name) {
  if (name == "devices") return cmd_devices;
  if (name == "eval") return cmd_eval;
  if (name == "hmd") return cmd_hmd;
  if (name == "validate") return cmd_validate;
  return nullptr;
}

}  // namespace vdfx::app
