/// @file
/// @brief The depth ranges and disparities the docs quote for each grain style.
#include "effects/grain_stereo.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdfx::effects {
namespace {

TEST(GrainStereo, DepthRangesFollowTheSettings) {
  GrainSettings s;
  EXPECT_EQ(grain_depth_range(GrainStyle::Headset, s).near_m, 0.05);
  EXPECT_EQ(grain_depth_range(GrainStyle::Surface, s).far_m, 10.0);
  const GrainDepthRange o = grain_depth_range(GrainStyle::ObjectCloud, s);
  EXPECT_EQ(o.near_m, 10.0);
  EXPECT_EQ(o.far_m, 40.0);
  const GrainDepthRange f = grain_depth_range(GrainStyle::FreeCloud, s);
  EXPECT_EQ(f.near_m, 0.1);
  EXPECT_DOUBLE_EQ(f.far_m, 2.5);  // sqrt(2^2 + 1.5^2)
}

TEST(GrainStereo, DisparityOfADistance) {
  // generic90: 1440 px over tan 52 + tan 47.
  const double f = 1440.0 / (std::tan(52.0 * kDegToRad) + std::tan(47.0 * kDegToRad));
  const Disparity plane = disparity_at(0.05, 0.063, f);
  EXPECT_NEAR(plane.vergence_deg, 64.4, 0.05);  // far beyond what the eyes fuse
  EXPECT_NEAR(plane.pixels, 1.26 * f, 1e-9);
  const Disparity sphere = disparity_at(10.0, 0.063, f);
  EXPECT_NEAR(sphere.vergence_deg, 0.361, 0.001);
  EXPECT_NEAR(sphere.pixels, 0.0063 * f, 1e-9);
}

}  // namespace
}  // namespace vdfx::effects
