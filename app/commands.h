/// @file
/// @brief The vdfx subcommands. Each takes the arguments after its name and returns the exit
/// code of the contract: 0 success, 1 the input was wrong, 2 usage error, 3 internal error.
#pragma once

#include <string>
#include <vector>

#include "app/command_table.h"

namespace vdfx::app {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const Args& args);
};

/// Every command with its function, in the order `vdfx --help` lists them.
const std::vector<Command>& commands();

/// Runs `vdfx ARGS...` (without the program name) with every command linked in (tests, the
/// media module), mapping exceptions to exit codes.
int run_main(const Args& args);

/// The commands that need no video, image or GL library (app/commands_light.cpp); null for the
/// others. The `vdfx` executable runs these itself and loads the media module for the others.
CommandFn light_command(const std::string& name);

int cmd_bench(const Args& args);
int cmd_devices(const Args& args);
int cmd_edit(const Args& args);
int cmd_eval(const Args& args);
int cmd_export(const Args& args);
int cmd_hmd(const Args& args);
int cmd_play(const Args& args);
int cmd_render(const Args& args);
int cmd_replay(const Args& args);
int cmd_validate(const Args& args);

}  // namespace vdfx::app
