#include "effects/coords.h"

#include <Eigen/Geometry>
#include <cmath>

namespace vdfx::effects {

Eigen::Vector3d to_unit(const Direction& d) {
  const double az = d.azimuth_deg * kDegToRad;
  const double alt = d.altitude_deg * kDegToRad;
  const double c = std::cos(alt);
  return {c * std::sin(az), std::sin(alt), -c * std::cos(az)};
}

Direction from_unit(const Eigen::Vector3d& v) {
  const double horizontal = std::hypot(v.x(), v.z());
  Direction d;
  d.altitude_deg = std::atan2(v.y(), horizontal) * kRadToDeg;
  d.azimuth_deg = horizontal > 0.0 ? std::atan2(v.x(), -v.z()) * kRadToDeg : 0.0;
  d.azimuth_deg = wrap_azimuth_deg(d.azimuth_deg);
  return d;
}

double wrap_azimuth_deg(double azimuth_deg) {
  double a = std::fmod(azimuth_deg, 360.0);
  if (a > 180.0) a -= 360.0;
  if (a <= -180.0) a += 360.0;
  return a;
}

Eigen::Vector2d to_equirect_uv(const Direction& d) {
  return {0.5 + d.azimuth_deg / 360.0, 0.5 - d.altitude_deg / 180.0};
}

Direction from_equirect_uv(const Eigen::Vector2d& uv) {
  return {wrap_azimuth_deg((uv.x() - 0.5) * 360.0), (0.5 - uv.y()) * 180.0};
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace vdfx::effects
