/// @file
/// @brief The command registry and the top-level dispatch (only the light commands linked in).
#include "app/cli/command_registry.h"

#include <unistd.h>

#include <exception>
#include <iostream>

#include "app/cli/command_functions.h"
#include "app/cli/stop_signals.h"
#include "io/input_error.h"

namespace vdfx::app {

const std::vector<Command>& commands() {
#define VDFX_COMMAND(name, home, summary) {#name, summary, VDFX_HOME_##home(name)},
#define VDFX_HOME_light(name) CommandHome::kLight, cmd_##name
#define VDFX_HOME_media(name) CommandHome::kMedia, nullptr
  static const std::vector<Command> list = {
#include "app/cli/commands.inc"
  };
#undef VDFX_COMMAND
  return list;
}

void print_help(std::ostream& out) {
  out << "vdfx: author view-dependent effects for 360-degree video\n\n"
         "usage: vdfx COMMAND [ARGS...]   (vdfx COMMAND --help for its options)\n\ncommands:\n";
  for (const Command& c : commands()) {
    std::string name = c.name;
    name.resize(10, ' ');
    out << "  " << name << c.summary << "\n";
  }
  out << "\n--verbose (anywhere): keep the media libraries' own messages (FFmpeg, OpenCV)\n"
         "exit codes: 0 success, 1 the input was wrong, 2 usage error, 3 internal error\n";
}

int run_guarded(const char* name, const std::function<int(const Args&)>& run, const Args& args) {
  try {
    return run(args);
  } catch (const Stopped& e) {
    // On a terminal the line starts fresh (after "^C", or a progress bar drawn in place).
    std::cerr << (::isatty(STDERR_FILENO) ? "\n" : "") << "vdfx " << name << ": " << stopped_by()
              << ": " << e.what() << "\n";
    return stop_signal() ? 128 + stop_signal() : kExitInternal;  // the signal ends it, not this
  } catch (const UsageError& e) {
    std::cerr << "vdfx " << name << ": " << e.what() << "\n";
    return kExitUsage;
  } catch (const io::InputError& e) {
    std::cerr << "vdfx " << name << ": " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "vdfx " << name << ": internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

namespace {

/// ARGS without --verbose before "--".
Args without_verbose(const Args& raw) {
  Args args;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == "--") {
      args.insert(args.end(), raw.begin() + static_cast<std::ptrdiff_t>(i), raw.end());
      break;
    }
    if (raw[i] != "--verbose") args.push_back(raw[i]);
  }
  return args;
}

}  // namespace

bool wants_verbose(const Args& args) {
  for (const std::string& a : args) {
    if (a == "--") return false;
    if (a == "--verbose") return true;
  }
  return false;
}

int dispatch(const Args& raw_args, const std::function<int(const Command&, const Args&)>& run) {
  const Args args = without_verbose(raw_args);
  if (args.empty()) {
    print_help(std::cerr);
    return kExitUsage;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(std::cout);
    return kExitOk;
  }
  if (args[0] == "--version") {
    std::cout << "vdfx 0.1.0\n";
    return kExitOk;
  }
  for (const Command& c : commands())
    if (args[0] == c.name) return run(c, Args(args.begin() + 1, args.end()));
  std::cerr << "vdfx: unknown command '" << args[0] << "' (vdfx --help lists them)\n";
  return kExitUsage;
}

}  // namespace vdfx::app
