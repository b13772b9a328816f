/// @file
/// @brief Every frame of a video through the camera tracker (camera_tracker.h), with the time the
/// analysis took apart from the decoding.
#pragma once

#include <functional>

#include "app/track/camera_tracker.h"
#include "effects/stereo_layout.h"
#include "io/frame_decoder.h"

namespace vdfx::app::track {

struct CameraEstimate {
  CameraTrack track;
  int width = 0;                  //!< analysis width used (at most the eye image's, per turn)
  double analysis_seconds = 0.0;  //!< reducing the frames and tracking: not the decoding
  /// The same, as CPU time of the calling thread: what the analysis cost where other work
  /// shares the machine (wall time then counts the waits too). OpenCV's own worker threads, where
  /// it starts any, are not in it.
  double analysis_cpu_seconds = 0.0;
  double decode_seconds = 0.0;
};

/// Decodes every frame of `decoder` from frame 0 (a frame that fails to decode is held) and tracks
/// the camera in the left eye's image of `layout`. `tick(fraction)` is called after each frame
/// (it may throw to stop). options.coverage_deg is taken from `layout`.
CameraEstimate estimate_camera(io::FrameDecoder& decoder, const effects::StereoLayout& layout,
                               CameraTrackOptions options,
                               const std::function<void(double)>& tick = {});

}  // namespace vdfx::app::track
