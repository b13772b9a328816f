/// @file
/// @brief `vdfx hmd openxr`: what the active OpenXR runtime offers (docs/openxr.md). `hmd` is a
/// light command; this part needs GL and the OpenXR loader, so it lives in the media module,
/// which installs it (app/cli/command_registry.h, set_hmd_openxr_command).
#pragma once

#include "app/cli/command_registry.h"

namespace vdfx::app {

/// ARGS are those after `openxr`: none, or --help.
int cmd_hmd_openxr(const Args& args);

}  // namespace vdfx::app
