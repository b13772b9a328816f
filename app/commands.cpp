/// @file
/// @brief Every command with its function (tests and the media module run them all in-process).
#include "app/commands.h"

#include <map>
#include <stdexcept>
#include <string>

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
  return dispatch(args, [](const CommandInfo& c, const Args& rest) {
    return run_guarded(c.name, function_of(c.name), rest);
  });
}

}  // namespace vdfx::app
