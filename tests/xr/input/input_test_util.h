/// @file
/// @brief Helpers for the input tests: view angles of poses, state comparison.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "xr/input/actions.h"

namespace vdfx::xr::test_util {

inline constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

/// Azimuth (positive right) and altitude of a pose's forward direction, degrees.
inline double azimuth_deg(const Pose& p) {
  const glm::dvec3 f = forward(p);
  return std::atan2(f.x, -f.z) * kRadToDeg;
}
inline double altitude_deg(const Pose& p) {
  return std::asin(forward(p).y) * kRadToDeg;
}

inline double angle_deg(const Pose& a, const Pose& b) {
  return std::acos(std::clamp(glm::dot(forward(a), forward(b)), -1.0, 1.0)) * kRadToDeg;
}

inline void expect_pose_eq(const Pose& a, const Pose& b, double tol, const char* what) {
  EXPECT_NEAR(a.orientation.w, b.orientation.w, tol) << what;
  EXPECT_NEAR(a.orientation.x, b.orientation.x, tol) << what;
  EXPECT_NEAR(a.orientation.y, b.orientation.y, tol) << what;
  EXPECT_NEAR(a.orientation.z, b.orientation.z, tol) << what;
  EXPECT_NEAR(a.position.x, b.position.x, tol) << what;
  EXPECT_NEAR(a.position.y, b.position.y, tol) << what;
  EXPECT_NEAR(a.position.z, b.position.z, tol) << what;
}

inline void expect_hand_eq(const HandState& a, const HandState& b, double tol, const char* what) {
  EXPECT_EQ(a.tracked, b.tracked) << what;
  if (!a.tracked || !b.tracked) return;
  expect_pose_eq(a.aim, b.aim, tol, what);
  expect_pose_eq(a.grip, b.grip, tol, what);
  EXPECT_NEAR(a.trigger, b.trigger, tol) << what;
  EXPECT_NEAR(a.squeeze, b.squeeze, tol) << what;
  EXPECT_NEAR(a.thumbstick.x, b.thumbstick.x, tol) << what;
  EXPECT_NEAR(a.thumbstick.y, b.thumbstick.y, tol) << what;
  EXPECT_EQ(a.primary, b.primary) << what;
  EXPECT_EQ(a.secondary, b.secondary) << what;
  EXPECT_EQ(a.menu, b.menu) << what;
  EXPECT_EQ(a.thumbstick_click, b.thumbstick_click) << what;
}

/// Equal actions (tol 0: bit-exact).
inline void expect_state_eq(const InputState& a, const InputState& b, double tol = 0.0) {
  EXPECT_EQ(a.head_tracked, b.head_tracked);
  expect_pose_eq(a.head, b.head, tol, "head");
  expect_hand_eq(a.left, b.left, tol, "left");
  expect_hand_eq(a.right, b.right, tol, "right");
}

}  // namespace vdfx::xr::test_util
