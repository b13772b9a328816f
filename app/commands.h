/// @file
/// @brief The vdfx subcommands. Each takes the arguments after its name and returns the exit
/// code of the contract: 0 success, 1 the input was wrong, 2 usage error, 3 internal error.
#pragma once

#include <string>
#include <vector>

namespace vdfx::app {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitInternal = 3 };

using Args = std::vector<std::string>;

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const Args& args);
};

/// Every command, in the order `vdfx --help` lists them.
const std::vector<Command>& commands();

/// Runs `vdfx ARGS...` (without the program name), mapping exceptions to exit codes.
int run_main(const Args& args);

int cmd_bench(const Args& args);
int cmd_devices(const Args& args);
int cmd_edit(const Args& args);
int cmd_eval(const Args& args);
int cmd_hmd(const Args& args);
int cmd_play(const Args& args);
int cmd_render(const Args& args);
int cmd_replay(const Args& args);
int cmd_validate(const Args& args);

}  // namespace vdfx::app
