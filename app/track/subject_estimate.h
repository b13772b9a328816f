/// @file
/// @brief A subject followed forwards and backwards from its start frame through every frame of a
/// video (subject_tracker.h): forwards by decoding on, backwards in chunks (each chunk decoded
/// forwards from a seek, then tracked in reverse), in the left eye's image of a stereo video.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "app/track/subject_tracker.h"
#include "effects/stereo_layout.h"
#include "io/frame_decoder.h"

namespace vdfx::app::track {

struct SubjectEstimate {
  std::vector<SubjectSample> samples;  //!< one per frame of the video
  int width = 0;                       //!< analysis equirect width (per turn)
};

/// `decoder` must hand RGB (any PixelFormat). `tick(fraction)` after each frame (may throw to
/// stop). options.coverage_deg is taken from `layout`. Throws io::InputError when the start frame
/// cannot be decoded.
SubjectEstimate estimate_subject(io::FrameDecoder& decoder, const effects::StereoLayout& layout,
                                 std::int64_t start, const Eigen::Vector3d& at,
                                 SubjectOptions options,
                                 const std::function<void(double)>& tick = {});

}  // namespace vdfx::app::track
