/// @file
/// @brief A decoded picture as the camera tracker sees it: the left eye's image of a stereo frame
/// (docs/stereo.md), its luma (the Y' plane as decoded, no colour conversion; grey of RGB
/// pictures), area-averaged down to the analysis size, 8 bits.
#pragma once

#include <opencv2/core.hpp>

#include "effects/stereo_layout.h"
#include "io/picture.h"

namespace vdfx::app::track {

/// CV_8UC1 of `size`. Throws std::invalid_argument for an empty picture.
cv::Mat analysis_grey(const io::Picture& picture, const effects::StereoLayout& layout,
                      cv::Size size);

}  // namespace vdfx::app::track
