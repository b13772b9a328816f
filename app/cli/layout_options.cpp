/// @file
/// @brief add_layout_options (see layout_options.h).
#include "app/cli/layout_options.h"

#include <string>

namespace vdfx::app {

void add_layout_options(CLI::App& cli, io::LayoutOverride& out) {
  cli.add_option_function<std::string>(
         "--layout",
         [&out](const std::string& name) { out.mode = effects::stereo_mode_from_name(name); },
         "how the frame holds the eyes (overrides the stream's tag): mono, top-bottom (left\n"
         "eye on top), left-right or right-left (the left half's eye named first)")
      ->check(CLI::IsMember({"mono", "top-bottom", "left-right", "right-left"}));
  cli.add_option_function<std::string>(
         "--coverage", [&out](const std::string& deg) { out.coverage_deg = std::stoi(deg); },
         "degrees of azimuth each eye's image spans, centred on azimuth 0 (overrides the\n"
         "stream's equirect bounds): 360, or 180 for VR180")
      ->check(CLI::IsMember({"360", "180"}));
}

}  // namespace vdfx::app
