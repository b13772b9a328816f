/// @file
/// @brief A video frame into a FlareSet's auto-light tracker: the OpenCV side of FlareSet
/// (effects/flare_set.h itself builds without OpenCV, for the web player's module).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "effects/flare_set.h"

namespace vdfx::effects {

/// Measures a video frame (RGB float equirect, effects/auto_light.h's find_brightest_region) for
/// the set's auto lights; nothing without auto lights or when `frame` was measured before.
void observe_frame(FlareSet& set, std::int64_t frame, const cv::Mat& rgb);

}  // namespace vdfx::effects
