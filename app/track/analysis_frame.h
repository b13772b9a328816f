/// @file
/// @brief A decoded picture as the camera tracker sees it: the left eye's image of a stereo frame
/// (docs/stereo.md), its luma (the Y' plane as decoded, no colour conversion; grey of RGB
/// pictures), area-averaged down to the analysis size, 8 bits.
#pragma once

#include <opencv2/core.hpp>

#include "effects/stereo_layout.h"
#include "io/picture.h"

namespace vdfx::app::track {

/// `image` area-averaged down to `size`: halved (2x2 means, OpenCV's fast path) while the half is
/// still at least `size`, then averaged over the remaining non-integer factor. OpenCV's area
/// resampling by a non-integer factor weighs every source pixel by its overlap: a 4K frame reduced
/// to 512 in one step took 35 ms, more than the whole tracking; this takes a tenth of it and
/// differs by about one grey level on average.
cv::Mat reduce_area(const cv::Mat& image, cv::Size size);

/// CV_8UC1 of `size`. Throws std::invalid_argument for an empty picture.
cv::Mat analysis_grey(const io::Picture& picture, const effects::StereoLayout& layout,
                      cv::Size size);

}  // namespace vdfx::app::track
