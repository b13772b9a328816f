/// @file
/// @brief Light tracks: great-circle interpolation between samples, held beyond the ends.
#include "effects/flare_light.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdfx::effects {
namespace {

double deg_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return angle_between(a, b) * kRadToDeg;
}

TEST(FlareLight, TrackInterpolatesAlongTheGreatCircleAtConstantSpeed) {
  const std::vector<LightSample> track{{10, {0.0, 0.0}}, {20, {90.0, 0.0}}, {30, {90.0, 60.0}}};
  EXPECT_LT(deg_between(light_on_track(track, 15), to_unit({45.0, 0.0})), 1e-12);
  EXPECT_LT(deg_between(light_on_track(track, 12), to_unit({18.0, 0.0})), 1e-12);
  EXPECT_LT(deg_between(light_on_track(track, 25), to_unit({90.0, 30.0})), 1e-12);
  // Off the meridian and equator, the path is the great circle: equal angles per frame.
  const std::vector<LightSample> diagonal{{0, {-30.0, 40.0}}, {8, {50.0, -10.0}}};
  const double total = deg_between(to_unit({-30.0, 40.0}), to_unit({50.0, -10.0}));
  for (int f = 0; f <= 8; ++f) {
    const Eigen::Vector3d p = light_on_track(diagonal, f);
    EXPECT_NEAR(deg_between(to_unit({-30.0, 40.0}), p), total * f / 8.0, 1e-9);
    EXPECT_NEAR(deg_between(p, to_unit({50.0, -10.0})), total * (8 - f) / 8.0, 1e-9);
  }
}

TEST(FlareLight, TrackHoldsItsEndsAndCrossesTheSeamTheShortWay) {
  const std::vector<LightSample> track{{10, {170.0, 5.0}}, {20, {-170.0, 5.0}}};
  EXPECT_EQ(light_on_track(track, 0), to_unit({170.0, 5.0}));
  EXPECT_EQ(light_on_track(track, 1000), to_unit({-170.0, 5.0}));
  const Direction mid = from_unit(light_on_track(track, 15));
  EXPECT_NEAR(std::abs(mid.azimuth_deg), 180.0, 1e-9);  // through the seam, not through 0
  const std::vector<LightSample> single{{5, {12.0, 34.0}}};
  EXPECT_EQ(light_on_track(single, 0), to_unit({12.0, 34.0}));
  EXPECT_EQ(light_on_track(single, 9), to_unit({12.0, 34.0}));
}

TEST(FlareLight, SlerpOfNearlyEqualVectorsStaysUnit) {
  const Eigen::Vector3d a = to_unit({10.0, 10.0}), b = to_unit({10.0, 10.0 + 1e-9});
  const Eigen::Vector3d m = slerp_unit(a, b, 0.5);
  EXPECT_NEAR(m.norm(), 1.0, 1e-15);
  EXPECT_LT(angle_between(a, m), 1e-10);
}

}  // namespace
}  // namespace vdfx::effects
