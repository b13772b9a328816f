/// @file
/// @brief One rendered view (the work of `vdfx render`), shared with tests and export jobs:
/// load the frame, interpolate the sidecar's effects, render on the CPU reference path or through
/// the GL compositor, optionally as one HMD eye with lens pre-distortion.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "effects/lens_model.h"
#include "effects/view_renderer.h"
#include "io/sidecar.h"
#include "xr/blur_method.h"
#include "xr/distortion_gl.h"
#include "xr/hmd_profile.h"

namespace vdfx::app {

struct RenderRequest {
  effects::Direction look;  //!< view centre (with --hmd: the head's forward direction)
  double roll_deg = 0.0;
  double hfov_deg = 90.0;  //!< without an HMD
  int width = 0;           //!< 0 with an HMD: the eye's resolution
  int height = 0;
  std::int64_t frame = 0;
  effects::RenderMode mode = effects::RenderMode::View;
  bool gpu = false;
  xr::BlurMethod blur = xr::BlurMethod::Exact;  //!< --gpu only (the CPU blur is the exact gather)
  int bake_width = 1024, bake_height = 512;    //!< --gpu --mode pixel: the parameter grid
  std::optional<xr::HmdProfile> hmd;
  xr::Eye eye = xr::Eye::Left;
  xr::DistortionSettings distortion{xr::DistortionMethod::None};
  std::string sidecar_name;  //!< names the sidecar when its values evaluate to NaN or infinity
};

/// Throws io::InputError naming `sidecar_name` and the view when an evaluated parameter is NaN
/// or infinite: the validator keeps the interpolation finite (docs/sidecar.md), and this is the
/// backstop that refuses to render or print such values instead of a black image or "null".
void require_finite(const effects::StackParams& params, const std::string& sidecar_name,
                    const effects::Direction& at, std::int64_t frame);

/// Frame `frame` of a video or still as RGB float, display-encoded. Throws io::InputError naming
/// the file when it is missing, unreadable, or has no such frame.
cv::Mat load_equirect_frame(const std::filesystem::path& input, std::int64_t frame);

/// Renders the request; returns 8-bit RGB. Throws io::InputError for bad input.
cv::Mat render_request(const std::filesystem::path& input, const io::Sidecar& sidecar,
                       const RenderRequest& request);

/// CPU reference of the lens pre-distortion: panel image of one eye from its undistorted eye
/// image (RGB float), per-channel sample positions from the exact inverse (Pixel) or an N x N
/// mesh (Mesh); black beyond the lens's monotonic limit and outside the eye image.
cv::Mat predistort_cpu(const cv::Mat& eye_rgb, const effects::EyeLens& eye,
                       const xr::DistortionSettings& settings);

/// "none", "pixel" or "mesh:N" (N in 2..257); throws std::invalid_argument with the reason.
xr::DistortionSettings parse_distortion(const std::string& text);

}  // namespace vdfx::app
