/// @file
/// @brief Where something is in a rendered image, for the tests that measure geometry from
/// pixels (flare glare and rings): intensity-weighted centroids in the contract's continuous
/// pixel coordinates (pixel (i, j) is centred at (i + 0.5, j + 0.5)).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <opencv2/core.hpp>

namespace vdfx::test_images {

/// Centroid of max(v - floor, 0) over a single-channel CV_32F image; NaN when nothing is above
/// the floor.
inline Eigen::Vector2d weighted_centroid(const cv::Mat& v, double floor = 0.0) {
  double sw = 0, sx = 0, sy = 0;
  for (int j = 0; j < v.rows; ++j)
    for (int i = 0; i < v.cols; ++i) {
      const double w = v.at<float>(j, i) - floor;
      if (w <= 0) continue;
      sw += w, sx += w * (i + 0.5), sy += w * (j + 0.5);
    }
  return sw > 0 ? Eigen::Vector2d(sx / sw, sy / sw) : Eigen::Vector2d::Constant(NAN);
}

/// Centroid of the part above half the image's maximum (a glare's core: a symmetric sprite's
/// centre, unmoved by its faint outskirts).
inline Eigen::Vector2d half_max_centroid(const cv::Mat& v) {
  double mx = 0;
  cv::minMaxLoc(v, nullptr, &mx);
  return weighted_centroid(v, 0.5 * mx);
}

}  // namespace vdfx::test_images
