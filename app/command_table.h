/// @file
/// @brief The list of vdfx commands (names and summaries) and the top-level dispatch: help,
/// version, unknown commands, exceptions mapped to exit codes.
///
/// Kept free of the commands themselves, so that the `vdfx` executable can dispatch without
/// linking the commands that need video, image or GL libraries: those live in the media module
/// (libvdfx_media.so, loaded on demand by app/main.cpp), and commands that need none of them
/// start without the dynamic loader resolving those libraries (docs/architecture.md, "Start-up").
#pragma once

#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace vdfx::app {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitInternal = 3 };

using Args = std::vector<std::string>;

/// A usage error found after parsing, where only the running system can tell (an option beyond
/// the GL implementation's largest texture, no display for a GL command): run_guarded reports it
/// as exit 2, like a parse error.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
using CommandFn = int (*)(const Args& args);

struct CommandInfo {
  const char* name;
  const char* summary;
};

/// Every command, in the order `vdfx --help` lists them.
const std::vector<CommandInfo>& command_infos();

void print_help(std::ostream& out);

/// Runs one command, mapping UsageError to exit 2, io::InputError to exit 1 and any other
/// exception to 3 (the message goes to stderr, prefixed with "vdfx NAME:").
int run_guarded(const char* name, const std::function<int(const Args&)>& run, const Args& args);

/// True when ARGS hold --verbose before any "--": keep the media libraries' own messages.
bool wants_verbose(const Args& args);

/// `vdfx ARGS...` (without the program name): no arguments, --help, --version and unknown
/// commands here; a known command goes to `run` with the arguments after its name. --verbose,
/// anywhere before "--", is taken out first (run_main acts on it: wants_verbose).
int dispatch(const Args& args, const std::function<int(const CommandInfo&, const Args&)>& run);

}  // namespace vdfx::app
