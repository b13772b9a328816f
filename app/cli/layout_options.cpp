/// @file
/// @brief add_layout_options (see layout_options.h).
#include "app/cli/layout_options.h"

#include <iostream>
#include <string>

#include "io/frame_decoder.h"
#include "io/sidecar.h"
#include "io/video_match.h"

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

effects::StereoLayout shown_layout(const io::VideoProperties& video, const io::LayoutOverride& cli,
                                   const io::VideoInfo* recorded,
                                   const std::filesystem::path& sidecar_path) {
  std::string hint;
  const effects::StereoLayout layout =
      io::resolve_video_layout(video, cli, recorded, sidecar_path, &hint);
  if (!hint.empty()) std::cerr << "vdfx: hint: " << video.path.string() << ": " << hint << "\n";
  if (recorded)
    if (const std::string w = io::video_mismatch(video, *recorded, sidecar_path); !w.empty())
      std::cerr << "vdfx: warning: " << w << "\n";
  return layout;
}

}  // namespace vdfx::app
