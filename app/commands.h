/// @file
/// @brief The vdfx subcommands. Each takes the arguments after its name and returns the exit
/// code of the contract: 0 success, 1 the input was wrong, 2 usage error, 3 internal error.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace vdfx::app {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitInternal = 3 };

using Args = std::vector<std::string>;

/// A usage error found after parsing, where only the running system can tell (an option beyond
/// the GL implementation's largest texture): run_main reports it as exit 2, like a parse error.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const Args& args);
};

/// Every command, in the order `vdfx --help` lists them.
const std::vector<Command>& commands();

/// Runs `vdfx ARGS...` (without the program name), mapping exceptions to exit codes.
int run_main(const Args& args);

int cmd_devices(const Args& args);
int cmd_edit(const Args& args);
int cmd_eval(const Args& args);
int cmd_hmd(const Args& args);
int cmd_play(const Args& args);
int cmd_render(const Args& args);
int cmd_replay(const Args& args);
int cmd_validate(const Args& args);

}  // namespace vdfx::app
