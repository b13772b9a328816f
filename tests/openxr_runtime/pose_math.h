/// @file
/// @brief Rigid poses in double precision for locating spaces (GLM: glm::dquat is (w, x, y, z)).
#pragma once

#include <openxr/openxr.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "tests/openxr_runtime/script.h"

namespace vdfx::test_runtime {

/// A pose of frame B in frame A: x_A = q * x_B + p.
struct Pose {
  glm::dquat q{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 p{0.0, 0.0, 0.0};
};

inline Pose compose(const Pose& a_from_b, const Pose& b_from_c) {
  return {a_from_b.q * b_from_c.q, a_from_b.p + a_from_b.q * b_from_c.p};
}

inline Pose inverse(const Pose& a) {
  const glm::dquat qi = glm::conjugate(a.q);
  return {qi, -(qi * a.p)};
}

inline Pose from_xr(const XrPosef& x) {
  return {glm::dquat(x.orientation.w, x.orientation.x, x.orientation.y, x.orientation.z),
          glm::dvec3(x.position.x, x.position.y, x.position.z)};
}

inline XrPosef to_xr(const Pose& p) {
  const glm::dquat q = glm::normalize(p.q);
  XrPosef x;
  x.orientation = {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z),
                   static_cast<float>(q.w)};
  x.position = {static_cast<float>(p.p.x), static_cast<float>(p.p.y), static_cast<float>(p.p.z)};
  return x;
}

inline Pose from_script(const ScriptPose& s) {
  return {glm::dquat(s.q[0], s.q[1], s.q[2], s.q[3]), glm::dvec3(s.p[0], s.p[1], s.p[2])};
}

/// OpenXR's rule for poses passed in: the orientation must be a unit quaternion (the spec lets a
/// runtime accept a norm within 1% of 1).
inline bool is_valid_pose(const XrPosef& x) {
  const XrQuaternionf& q = x.orientation;
  const double n2 = double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z + double(q.w) * q.w;
  return std::isfinite(n2) && n2 > 0.98 && n2 < 1.02 && std::isfinite(x.position.x) &&
         std::isfinite(x.position.y) && std::isfinite(x.position.z);
}

}  // namespace vdfx::test_runtime
