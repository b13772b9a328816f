/// @file
/// @brief The command registry (app/cli/commands.inc: name, summary, light or media, function)
/// and the top-level dispatch: help, version, unknown commands, exceptions mapped to exit codes.
///
/// The registry holds the functions of the light commands only, so that the `vdfx` executable
/// can dispatch without linking the commands that need video, image or GL libraries: those run
/// from the media module (libvdfx_media.so, loaded on demand by app/cli/main.cpp, whose own table
/// of every function is expanded from the same list: app/media/media_commands.h).
#pragma once

#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace vdfx::app {

enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,
  kExitUsage = 2,
  kExitInternal = 3,
  /// Never seen by a user: a light command whose asked-for part needs the media module (`vdfx hmd
  /// openxr`: GL and the OpenXR loader) returns it, and app/cli/main.cpp runs the command again
  /// from the module.
  kExitRunInMediaModule = 100,
};

/// The media module's implementation of `vdfx hmd openxr`, installed by the module at start
/// (app/media/media_commands.cpp); unset in the `vdfx` executable, whose cmd_hmd then answers
/// kExitRunInMediaModule.
void set_hmd_openxr_command(int (*command)(const std::vector<std::string>& args));

using Args = std::vector<std::string>;

/// A usage error found after parsing, where only the running system can tell (an option beyond
/// the GL implementation's largest texture, no display for a GL command): run_guarded reports it
/// as exit 2, like a parse error.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
using CommandFn = int (*)(const Args& args);

/// Where a command's code lives (app/cli/commands.inc).
enum class CommandHome {
  kLight,  //!< in the `vdfx` executable: no video, image or GL library
  kMedia,  //!< in libvdfx_media.so
};

struct Command {
  const char* name;
  const char* summary;
  CommandHome home;
  CommandFn light_run;  //!< the function of a light command; null for a media command
};

/// Every command, in the order `vdfx --help` lists them.
const std::vector<Command>& commands();

void print_help(std::ostream& out);

/// Runs one command, mapping UsageError to exit 2, io::InputError to exit 1 and any other
/// exception to 3 (the message goes to stderr, prefixed with "vdfx NAME:"). A command stopped by
/// a signal (app::Stopped, app/cli/stop_signals.h) is said as "vdfx NAME: stopped by SIGINT: ...";
/// the caller then ends the process by that signal (end_by_stop_signal).
int run_guarded(const char* name, const std::function<int(const Args&)>& run, const Args& args);

/// True when ARGS hold --verbose before any "--": keep the media libraries' own messages.
bool wants_verbose(const Args& args);

/// `vdfx ARGS...` (without the program name): no arguments, --help, --version and unknown
/// commands here; a known command goes to `run` with the arguments after its name. --verbose,
/// anywhere before "--", is taken out first (the caller acts on it: wants_verbose).
int dispatch(const Args& args, const std::function<int(const Command&, const Args&)>& run);

}  // namespace vdfx::app
