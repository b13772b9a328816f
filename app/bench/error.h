/// @file
/// @brief The error measure of `vdfx bench`'s image knobs: differences in 8-bit steps.
#pragma once

#include <opencv2/core.hpp>

#include "app/bench/report.h"

namespace vdfx::app::bench {

/// Max, RMS (and mean into *mean) of |a - b| over all channels in 8-bit steps (x 255), after
/// clamping both to [0, 1]; a and b are same-size float images of 3 or 4 channels (only the
/// first 3 count).
ErrorStats steps_error(const cv::Mat& a, const cv::Mat& b, double* mean = nullptr);

}  // namespace vdfx::app::bench
