/// @file
/// @brief View directions and their conversions (contract: "Coordinates and time").
///
/// Azimuth in degrees, (-180, 180], 0 at the centre column of the equirect frame, positive to the
/// right; altitude in degrees, [-90, 90], positive up. Unit vectors use OpenXR axes: +x right,
/// +y up, -z forward, so azimuth 0 / altitude 0 is (0, 0, -1) and azimuth +90 is +x.
#pragma once

#include <Eigen/Core>

namespace vdfx::effects {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

struct Direction {
  double azimuth_deg = 0.0;   //!< (-180, 180], positive to the right
  double altitude_deg = 0.0;  //!< [-90, 90], positive up
  /// Exactly the same numbers (no angular tolerance).
  bool operator==(const Direction&) const = default;
};

/// Unit vector of a direction (OpenXR axes).
Eigen::Vector3d to_unit(const Direction& d);

/// Direction of a (not necessarily unit, non-zero) vector; azimuth is 0 at the poles.
Direction from_unit(const Eigen::Vector3d& v);

/// Wraps any azimuth into (-180, 180].
double wrap_azimuth_deg(double azimuth_deg);

/// Equirect texture coordinates: u = 0.5 + az/360, v = 0.5 - alt/180 (v = 0 is the top row).
Eigen::Vector2d to_equirect_uv(const Direction& d);
Direction from_equirect_uv(const Eigen::Vector2d& uv);

/// Angle in radians between two vectors, accurate near 0 and pi: atan2(|a x b|, a . b).
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace vdfx::effects
