/// @file
/// @brief Rigid poses (GLM, double precision) for panels and controllers.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace vdfx::ui {

/// Maps local coordinates to world: world = position + orientation * local.
struct Pose {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  //!< glm order (w, x, y, z)

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
};

}  // namespace vdfx::ui
