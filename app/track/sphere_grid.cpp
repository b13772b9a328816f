/// @file
/// @brief SphereGrid: analysis pixels and their directions.
#include "app/track/sphere_grid.h"

#include <cmath>

#include "effects/coords.h"

namespace vdfx::app::track {

SphereGrid SphereGrid::of_width(int width, int coverage_deg) {
  return {width * coverage_deg / 360, width / 2, coverage_deg};
}

Eigen::Vector3d SphereGrid::unit_at(const cv::Point2f& p) const {
  const double az = (static_cast<double>(p.x) / width - 0.5) * coverage_deg;
  const double alt = 90.0 - 180.0 * static_cast<double>(p.y) / height;
  return effects::to_unit({az, alt});
}

cv::Point2f SphereGrid::pixel_of(const Eigen::Vector3d& n) const {
  // atan2 directly (not effects::from_unit's wrapped degrees): the same numbers, fewer steps on
  // the per-point path.
  const double az = std::atan2(n.x(), -n.z()) * effects::kRadToDeg;
  const double alt = std::atan2(n.y(), std::hypot(n.x(), n.z())) * effects::kRadToDeg;
  const double x = (0.5 + az / coverage_deg) * width, y = (0.5 - alt / 180.0) * height;
  return {wrap_x(static_cast<float>(x)), static_cast<float>(y)};
}

float SphereGrid::wrap_x(float x) const {
  if (!wraps()) return x;
  const auto w = static_cast<float>(width);
  x = std::fmod(x, w);
  if (x < 0.0f) x += w;
  return x >= w ? 0.0f : x;
}

bool SphereGrid::inside(const cv::Point2f& p) const {
  return p.y >= 0.0f && p.y < static_cast<float>(height) && p.x >= 0.0f &&
         p.x < static_cast<float>(width);
}

}  // namespace vdfx::app::track
