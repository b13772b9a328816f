/// @file
/// @brief `vdfx replay`: a recorded session stepped through the Editor headless, as fast as it
/// goes, at every recorded sample time; the sidecar it leaves, and optionally mirror-like frames.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "effects/view_camera.h"
#include "io/sidecar.h"
#include "io/video_layout.h"
#include "ui/panel.h"
#include "xr/headset/pose.h"

namespace vdfx::app {

struct ReplayOptions {
  std::filesystem::path recording;
  std::filesystem::path video;
  //! Start from it (else from an existing sidecar_out, else an empty sidecar).
  std::optional<std::filesystem::path> sidecar_in;
  std::filesystem::path sidecar_out;
  bool force = false;  //!< an existing sidecar_out may be replaced (io/sidecar_target.h)
  std::optional<std::filesystem::path> frames_dir;  //!< write mirror-like PNGs here
  int frame_images = 5;  //!< evenly spaced over the session, the last sample included
  int width = 1280;      //!< of each PNG
  int height = 720;
  double hfov_deg = 90.0;
  std::string log_prefix = "vdfx replay";
  /// --layout / --coverage (docs/stereo.md); the frames show the left eye of stereo video.
  io::LayoutOverride layout;
};

struct ReplayResult {
  io::Sidecar sidecar;
  std::size_t samples = 0;
  std::vector<std::filesystem::path> images;
  std::vector<std::string> messages;  //!< warnings and notes for the user
};

/// Runs the session. An existing sidecar_out is what the session is replayed onto, or replaced
/// only with `force` (io::resolve_sidecar_target). Throws io::InputError for a bad recording
/// (file and line), video or sidecar, and for an sidecar_out that would be replaced.
ReplayResult run_replay(const ReplayOptions& options);

/// Draws the panels (premultiplied RGBA textures on their world quads) over an RGB8 view seen
/// from `eye` through `camera` (nearest texel).
void overlay_panels(cv::Mat& rgb8, const effects::ViewCamera& camera, const glm::dvec3& eye,
                    const std::vector<ui::Panel*>& panels);

}  // namespace vdfx::app
