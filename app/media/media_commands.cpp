/// @file
/// @brief Every command with its function (the media module runs them all in-process).
#include "app/media/media_commands.h"

#include <string>
#include <utility>

#include "app/cli/command_functions.h"
#include "app/window/hmd_openxr_command.h"
#include "io/library_logs.h"
#include "xr/render/gl_context.h"

namespace vdfx::app {

CommandFn command_function(std::string_view name) {
#define VDFX_COMMAND(name, home, summary) {#name, cmd_##name},
  static constexpr std::pair<std::string_view, CommandFn> kFunctions[] = {
#include "app/cli/commands.inc"
  };
#undef VDFX_COMMAND
  for (const auto& [n, fn] : kFunctions)
    if (n == name) return fn;
  return nullptr;
}

namespace {

/// Runs `fn`. No display or no GL 4.3 here is how the command was run, not the input or a bug:
/// a usage error (exit 2).
int gl_unavailable_is_usage(CommandFn fn, const Args& args) {
  try {
    return fn(args);
  } catch (const xr::GlUnavailableError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace

int run_main(const Args& args) {
  if (!wants_verbose(args)) io::quiet_library_logs();
  set_hmd_openxr_command(cmd_hmd_openxr);
  return dispatch(args, [](const Command& c, const Args& rest) {
    const CommandFn fn = command_function(c.name);
    return run_guarded(
        c.name, [fn](const Args& a) { return gl_unavailable_is_usage(fn, a); }, rest);
  });
}

}  // namespace vdfx::app
