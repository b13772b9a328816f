#include "effects/coords.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdfx::effects {
namespace {

const struct {
  Direction d;
  Eigen::Vector3d unit;
} kAxes[] = {
    {{0, 0}, {0, 0, -1}},  // forward is -z (OpenXR)
    {{90, 0}, {1, 0, 0}},  // positive azimuth turns right
    {{-90, 0}, {-1, 0, 0}}, {{180, 0}, {0, 0, 1}}, {{0, 90}, {0, 1, 0}},  // positive altitude is up
    {{0, -90}, {0, -1, 0}},
};

TEST(Coords, AxesFollowTheContract) {
  for (const auto& row : kAxes) {
    EXPECT_LT((to_unit(row.d) - row.unit).norm(), 1e-15)
        << "az " << row.d.azimuth_deg << " alt " << row.d.altitude_deg;
  }
}

TEST(Coords, RoundTripAndWrap) {
  for (double az = -179.5; az <= 180.0; az += 7.25) {
    for (double alt = -89.0; alt <= 89.0; alt += 11.0) {
      const Direction back = from_unit(to_unit({az, alt}));
      EXPECT_NEAR(back.azimuth_deg, az, 1e-9);
      EXPECT_NEAR(back.altitude_deg, alt, 1e-9);
    }
  }
  EXPECT_DOUBLE_EQ(wrap_azimuth_deg(-180.0), 180.0);
  EXPECT_DOUBLE_EQ(wrap_azimuth_deg(540.0), 180.0);
  EXPECT_DOUBLE_EQ(wrap_azimuth_deg(-190.0), 170.0);
}

TEST(Coords, EquirectUvFollowsTheContract) {
  const Eigen::Vector2d uv = to_equirect_uv({90.0, 45.0});
  EXPECT_DOUBLE_EQ(uv.x(), 0.75);
  EXPECT_DOUBLE_EQ(uv.y(), 0.25);
}

TEST(Coords, AngleIsAccurateForTinyAngles) {
  const double tiny = 1e-9;
  const Eigen::Vector3d a = to_unit({0, 0});
  const Eigen::Vector3d b = to_unit({tiny * kRadToDeg, 0});
  // acos(dot) would return 0 here: the cosine of 1e-9 rounds to 1.
  EXPECT_NEAR(angle_between(a, b), tiny, 1e-20);
  EXPECT_NEAR(angle_between(a, -a), kPi, 1e-15);
}

}  // namespace
}  // namespace vdfx::effects
