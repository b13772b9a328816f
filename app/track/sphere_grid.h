/// @file
/// @brief The pixels of a (small, grey) equirect analysis image and the unit directions they see
/// (contract: u = 0.5 + azimuth / coverage, v = 0.5 - altitude / 180; pixel (i, j) is centred at
/// (i + 0.5, j + 0.5)). A 360 image wraps at its left and right edges; a VR180 one (coverage 180)
/// spans azimuth -90..90 and does not.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace vdfx::app::track {

struct SphereGrid {
  int width = 512;
  int height = 256;
  int coverage_deg = 360;

  /// The analysis image of `width` pixels per 360 degrees: width x width/2, or width/2 x
  /// width/2 for a half turn (the same pixels per degree).
  static SphereGrid of_width(int width, int coverage_deg);
  cv::Size size() const { return {width, height}; }
  bool wraps() const { return coverage_deg == 360; }
  /// Degrees of arc one pixel spans on the equator.
  double degrees_per_pixel() const { return 180.0 / height; }

  /// The unit direction (OpenXR axes) through continuous pixel coordinates p.
  Eigen::Vector3d unit_at(const cv::Point2f& p) const;
  /// Continuous pixel coordinates of a direction (x in [0, width) for a 360 image; outside
  /// [0, width) for a direction beyond a half turn's edges).
  cv::Point2f pixel_of(const Eigen::Vector3d& n) const;
  /// x wrapped into [0, width) for a 360 image; unchanged otherwise.
  float wrap_x(float x) const;
  /// Whether a point lies inside the image (and, for a half turn, inside its columns).
  bool inside(const cv::Point2f& p) const;
};

}  // namespace vdfx::app::track
