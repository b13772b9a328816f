/// @file
/// @brief A grey analysis equirect turned by a rotation, so that an earlier key frame can be
/// matched against a later one with small residual motion whatever the rotation between them
/// (optical flow follows small shifts; a large rotation also turns and stretches the patches).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "app/track/sphere_grid.h"

namespace vdfx::app::track {

/// The image whose pixel at direction c shows `grey` at direction r^T c: what `grey` looks like
/// from a frame whose directions are r times grey's. Bilinear; columns wrap for a 360 image;
/// directions outside a half turn's image are black.
cv::Mat warp_equirect(const cv::Mat& grey, const SphereGrid& grid, const Eigen::Matrix3d& r);

/// `grey` with `pad` columns added on each side (a 360 image: wrapped round from the other edge, so
/// flow crosses the seam; a half turn: repeated) and `pad` rows above and below (repeated).
cv::Mat pad_for_flow(const cv::Mat& grey, const SphereGrid& grid, int pad);

}  // namespace vdfx::app::track
