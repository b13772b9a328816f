/// @file
/// @brief Every command with its function (tests and the media module run them all in-process).
#include "app/commands.h"

#include <map>
#include <stdexcept>
#include <string>

#include "io/library_logs.h"
#include "xr/gl_context.h"

namespace vdfx::app {
namespace {

CommandFn function_of(const std::string& name) {
  static const std::map<std::string, CommandFn> fns = {
      {"bench", cmd_bench},       {"devices", cmd_devices}, {"edit", cmd_edit},
      {"eval", cmd_eval},         {"export", cmd_export},   {"hmd", cmd_hmd},
      {"play", cmd_play},         {"render", cmd_render},   {"replay", cmd_replay},
      {"validate", cmd_validate},
  };
  const auto it = fns.find(name);
  if (it == fns.end()) throw std::logic_error("command '" + name + "' has no function");
  return it->second;
}

/// Runs `fn`. No display or no GL 4.3 here is how the command was run, not the input or a bug:
/// a usage error (exit 2).
int gl_unavailable_is_usage(CommandFn fn, const Args& args) {
#if VDFX_WITH_GL
  try {
    return fn(args);
  } catch (const xr::GlUnavailableError& e) {
    throw UsageError(e.what());
  }
#else
  return fn(args);
#endif
}

}  // namespace

const std::vector<Command>& commands() {
  static const std::vector<Command> list = [] {
    std::vector<Command> v;
    for (const CommandInfo& c : command_infos())
      v.push_back({c.name, c.summary, function_of(c.name)});
    return v;
  }();
  return list;
}

int run_main(const Args& args) {
  if (!wants_verbose(args)) io::quiet_library_logs();
  return dispatch(args, [](const CommandInfo& c, const Args& rest) {
    const CommandFn fn = function_of(c.name);
    return run_guarded(
        c.name, [fn](const Args& a) { return gl_unavailable_is_usage(fn, a); }, rest);
  });
}

}  // namespace vdfx::app
