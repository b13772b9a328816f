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
#include "io/picture.h"
#include "io/sidecar.h"
#include "io/video_layout.h"
#include "xr/headset/hmd_profile.h"
#include "xr/render/blur_method.h"
#include "xr/render/distortion_gl.h"

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
  int bake_width = 1024, bake_height = 512;     //!< --gpu --mode pixel: the parameter grid
  std::optional<xr::HmdProfile> hmd;
  xr::Eye eye = xr::Eye::Left;  //!< the HMD's eye, and the stereo video's half (docs/stereo.md)
  bool eye_given = false;       //!< --eye was given (without --hmd it needs a stereo video)
  io::LayoutOverride layout;    //!< --layout / --coverage
  xr::DistortionSettings distortion{xr::DistortionMethod::None};
  std::string sidecar_name;  //!< names the sidecar when its values evaluate to NaN or infinity
  /// Display time that picks the grain pattern (docs/grain.md); default the frame's start,
  /// effects::frame_display_time_ns(frame, fps).
  std::optional<std::int64_t> display_time_ns;
};

/// Index (in Sidecar::grains) of the first grain effect with no CPU reference (a volumetric
/// style: object_cloud, free_cloud), which `vdfx render` draws only with --gpu.
std::optional<std::size_t> first_gpu_only_grain(const io::Sidecar& sidecar);

/// Frame `frame` of a video or still as the decoder hands it over (Y'CbCr planes or RGB).
/// Throws io::InputError naming the file when it is missing, unreadable, or has no such frame.
io::Picture load_equirect_picture(const std::filesystem::path& input, std::int64_t frame,
                                  io::VideoProperties* properties = nullptr);

/// Frame `frame` of a video or still as RGB float, display-encoded, each eye of `layout`
/// converted from its own planes (io::to_rgb_by_eye). Throws as above.
cv::Mat load_equirect_frame(const std::filesystem::path& input, std::int64_t frame,
                            const effects::StereoLayout& layout);

/// Renders the request; returns 8-bit RGB. Throws io::InputError for bad input.
cv::Mat render_request(const std::filesystem::path& input, const io::Sidecar& sidecar,
                       const RenderRequest& request);

/// `vdfx render`'s work once its options are parsed (the HMD profile loaded): `out` checked
/// against the inputs, the sidecar read, the view rendered and written as an 8-bit sRGB PNG.
/// Returns the image's size. Throws io::InputError for bad input, app::UsageError for a sidecar
/// that needs `gpu` or a size the GL implementation cannot render.
cv::Size render_to_png(const std::filesystem::path& input, const std::filesystem::path& sidecar,
                       const RenderRequest& request, const std::filesystem::path& out);

/// CPU reference of the lens pre-distortion: panel image of one eye from its undistorted eye
/// image (RGB float), per-channel sample positions from the exact inverse (Pixel) or an N x N
/// mesh (Mesh); black beyond the lens's monotonic limit and outside the eye image.
cv::Mat predistort_cpu(const cv::Mat& eye_rgb, const effects::EyeLens& eye,
                       const xr::DistortionSettings& settings);

/// "none", "pixel" or "mesh:N" (N in 2..257); throws std::invalid_argument with the reason.
xr::DistortionSettings parse_distortion(const std::string& text);

}  // namespace vdfx::app
