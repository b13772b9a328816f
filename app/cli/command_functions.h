/// @file
/// @brief The declaration of every command's function, `int cmd_NAME(const Args&)`, expanded from
/// the registry (app/cli/commands.inc). Each command's file includes it, so its definition is
/// checked against the registry; only the light ones are linked into the `vdfx` executable.
#pragma once

#include "app/cli/command_registry.h"

namespace vdfx::app {

#define VDFX_COMMAND(name, home, summary) int cmd_##name(const Args& args);
#include "app/cli/commands.inc"
#undef VDFX_COMMAND

}  // namespace vdfx::app
