/// @file
/// @brief Rigid poses (GLM, double precision) and where they look: heads, eyes, controllers, UI
/// panels.
///
/// One type for xr/ and ui/ (they re-export it as xr::Pose and ui::Pose). Axes are OpenXR's
/// (+x right, +y up, -z forward); directions and angle constants are the contract's
/// (effects/coords.h).
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "effects/coords.h"

namespace vdfx::math {

/// Maps local coordinates to world: world = position + orientation * local.
struct Pose {
  glm::dvec3 position{0.0};                    //!< metres
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  //!< unit, glm order (w, x, y, z)

  glm::dvec3 transform(const glm::dvec3& local) const { return position + orientation * local; }
  glm::dvec3 rotate(const glm::dvec3& local) const { return orientation * local; }
  Pose inverse() const {
    const glm::dquat inv = glm::conjugate(orientation);
    return {inv * -position, inv};
  }
  /// this * local: apply local first, then this.
  Pose operator*(const Pose& local) const {
    return {transform(local.position), glm::normalize(orientation * local.orientation)};
  }
  bool operator==(const Pose&) const = default;
};

/// The forward direction (-z) of a pose, unit length.
inline glm::dvec3 forward(const Pose& pose) {
  return glm::normalize(pose.orientation * glm::dvec3(0.0, 0.0, -1.0));
}

/// Where a pose looks, as the contract's azimuth and altitude (for a head: its view direction).
inline effects::Direction forward_direction(const Pose& pose) {
  const glm::dvec3 f = forward(pose);
  return effects::from_unit(Eigen::Vector3d(f.x, f.y, f.z));
}

/// Orientation looking at azimuth/altitude (degrees, contract conventions: azimuth positive to the
/// right, altitude positive up), no roll.
inline glm::dquat look_rotation(double azimuth_deg, double altitude_deg) {
  // Yaw about +y (a positive angle turns -z towards -x, i.e. left, hence the minus), then pitch
  // about the turned +x (a positive angle lifts -z towards +y).
  return glm::angleAxis(-azimuth_deg * effects::kDegToRad, glm::dvec3(0, 1, 0)) *
         glm::angleAxis(altitude_deg * effects::kDegToRad, glm::dvec3(1, 0, 0));
}

}  // namespace vdfx::math
