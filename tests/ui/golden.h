/// @file
/// @brief Golden-image comparison for ui tests (style point 8): max and mean tolerances, actual
/// and diff PNGs written to the build tree on failure, VDFX_BLESS=1 rewrites the goldens.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace vdfx::ui::test {

/// Compares a premultiplied RGBA8 image with tests/ui/golden/<name>.png (straight-alpha RGBA).
/// Tolerances are on 8-bit channel values of the premultiplied images. Returns an empty string
/// on success, else what failed and where the actual and diff images were written.
std::string compare_with_golden(const cv::Mat& premultiplied_rgba, const std::string& name,
                                double max_tolerance, double mean_tolerance);

/// The straight-alpha image composited over a mid-grey backdrop, as BGR: how a user sees a
/// panel in front of video. Written next to the actual images for review.
cv::Mat preview_over_grey(const cv::Mat& premultiplied_rgba);

std::string golden_dir();
std::string output_dir();

}  // namespace vdfx::ui::test
