/// @file
/// @brief The viewer's-path export: the flat video a viewer saw along a recorded head path. Head
/// orientations are resampled at the video's frame times (slerp between the recording's
/// samples), each frame is rendered as `vdfx render --mode view` renders one view (cyclopean:
/// the head's look and roll, no eye offset; the video is a sphere at infinity), with the
/// view-dependent effects interpolated once at the view's centre.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/coords.h"
#include "effects/stack_interpolator.h"
#include "effects/stereo_layout.h"
#include "io/frame_time.h"
#include "io/recording.h"
#include "xr/headset/render_view.h"

namespace vdfx::app {

struct HeadSample {
  std::int64_t t_ns = 0;  //!< from the recording's first head sample
  glm::dquat q{1.0, 0.0, 0.0, 0.0};
};

/// The recording's head samples (raw HID lines skipped), times relative to the first sample.
/// Throws io::InputError naming the recording when it holds no head sample.
std::vector<HeadSample> head_path(const io::Recording& recording);

/// Head orientation `t_ns` after the first sample: slerp between the samples around it, the
/// first or last one held outside the recording.
glm::dquat head_at(const std::vector<HeadSample>& path, std::int64_t t_ns);

struct PathView {
  effects::Direction look;
  double roll_deg = 0.0;  //!< positive turns the image clockwise as the viewer sees it
};

/// The view of video frame `frame`: the head at the frame's start time (io::frame_start_ns).
PathView path_view(const std::vector<HeadSample>& path, std::int64_t frame, io::Rational fps);

/// The last frame the recording covers: the frame shown at its last sample's time.
std::int64_t path_last_frame(const std::vector<HeadSample>& path, io::Rational fps);

/// Flare and grain (app/export/layers.h) attach here: called on each rendered view (unclamped
/// RGB float, after the view-dependent effects, before the output clamp) with the decoded frame
/// (RGB float equirect) and the view it was rendered for.
using ViewLayersHook = std::function<void(cv::Mat& rgb, const cv::Mat& equirect,
                                          const xr::RenderView& view, std::int64_t frame)>;

struct PathRenderSettings {
  double hfov_deg = 90.0;
  int width = 1280, height = 720;
  ViewLayersHook view_layers;  //!< empty: the six effects only
  /// The source frame's stereo layout and coverage, and the eye whose image is shown.
  effects::StereoLayout layout;
  effects::EyeIndex eye = effects::EyeIndex::Left;
};

/// One frame of the viewer's-path export: RGB float (CV_32FC3, unclamped: the encoder's
/// conversion clamps), what `vdfx render --mode view` renders for (look, roll, frame, fov, size)
/// on the CPU before its 8-bit output step. Never rounded to 8 bits, so a 10-bit export keeps
/// the levels of a deeper source (docs/export.md, "10 bits").
cv::Mat render_path_frame(const cv::Mat& equirect, const effects::StackInterpolator& stack,
                          const PathView& view, std::int64_t frame,
                          const PathRenderSettings& settings);

}  // namespace vdfx::app
