#include "app/commands.h"

#include <exception>
#include <iostream>

#include "io/input_error.h"
#include "io/library_logs.h"
#include "xr/gl_context.h"

namespace vdfx::app {

const std::vector<Command>& commands() {
  static const std::vector<Command> list = {
      {"devices", "list HID input devices (gamepads, SpaceMouse) and their ids for --input hid:", cmd_devices},
      {"edit", "the in-headset editor (no VIDEO: the bundled demo)", cmd_edit},
      {"eval", "print the interpolated parameters of every effect at given views", cmd_eval},
      {"hmd", "list the simulated headsets, or show one (vdfx hmd list | show NAME)", cmd_hmd},
      {"play", "play a video with its effects in the simulated headset", cmd_play},
      {"render", "render one view of a panorama or video frame to a PNG", cmd_render},
      {"replay", "replay a recorded editing session headless and write its sidecar", cmd_replay},
      {"validate", "check a sidecar file; list every problem", cmd_validate},
  };
  return list;
}

namespace {
void print_help(std::ostream& out) {
  out << "vdfx: author view-dependent effects for 360-degree video\n\n"
         "usage: vdfx COMMAND [ARGS...]   (vdfx COMMAND --help for its options)\n\ncommands:\n";
  for (const auto& c : commands()) {
    std::string name = c.name;
    name.resize(10, ' ');
    out << "  " << name << c.summary << "\n";
  }
  out << "\n--verbose (anywhere): keep the media libraries' own messages (OpenCV, FFmpeg)\n"
         "exit codes: 0 success, 1 the input was wrong, 2 usage error, 3 internal error\n";
}
}  // namespace

int run_main(const Args& raw_args) {
  // --verbose, anywhere before "--": the media libraries' own messages stay on.
  Args args;
  bool verbose = false;
  for (std::size_t i = 0; i < raw_args.size(); ++i) {
    if (raw_args[i] == "--") {
      args.insert(args.end(), raw_args.begin() + static_cast<std::ptrdiff_t>(i), raw_args.end());
      break;
    }
    if (raw_args[i] == "--verbose") verbose = true;
    else args.push_back(raw_args[i]);
  }
  if (!verbose) io::quiet_library_logs();
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
  for (const auto& c : commands()) {
    if (args[0] != c.name) continue;
    try {
      return c.run(Args(args.begin() + 1, args.end()));
    } catch (const UsageError& e) {
      std::cerr << "vdfx " << c.name << ": " << e.what() << "\n";
      return kExitUsage;
#if VDFX_WITH_GL
    } catch (const xr::GlUnavailableError& e) {  // no display or GL 4.3 here: how it was run
      std::cerr << "vdfx " << c.name << ": " << e.what() << "\n";
      return kExitUsage;
#endif
    } catch (const io::InputError& e) {
      std::cerr << "vdfx " << c.name << ": " << e.what() << "\n";
      return kExitBadInput;
    } catch (const std::exception& e) {
      std::cerr << "vdfx " << c.name << ": internal error: " << e.what() << "\n";
      return kExitInternal;
    }
  }
  std::cerr << "vdfx: unknown command '" << args[0] << "' (vdfx --help lists them)\n";
  return kExitUsage;
}

}  // namespace vdfx::app
