/// @file
/// @brief Every command with its function, expanded from the one registry
/// (app/cli/commands.inc): the media module runs them all in-process.
#pragma once

#include <string_view>

#include "app/cli/command_registry.h"

namespace vdfx::app {

/// The function of any command (light or media); null for a name the registry does not hold.
CommandFn command_function(std::string_view name);

/// Runs `vdfx ARGS...` (without the program name) with every command linked in, mapping
/// exceptions to exit codes; the media libraries' own messages are quiet unless --verbose.
int run_main(const Args& args);

}  // namespace vdfx::app
