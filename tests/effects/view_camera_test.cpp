/// @file
/// @brief ViewCamera: centre ray, right/up/roll conventions, FOV, projection round trip.
#include "effects/view_camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdfx::effects {
namespace {

const struct {
  double az, alt, roll;
} kPoses[] = {
    {0, 0, 0}, {30, 0, 0}, {-150, 20, 0}, {180, -45, 30}, {75, 60, -90}, {10, 89, 45},
};

TEST(ViewCamera, CentrePixelLooksAtTheViewDirection) {
  for (const auto& p : kPoses) {
    // Odd size: pixel (50, 30) has its centre at (50.5, 30.5), the image centre.
    const ViewCamera cam = ViewCamera::from_horizontal_fov({{p.az, p.alt}, p.roll}, 90.0, 101, 61);
    const Eigen::Vector3d want = to_unit({p.az, p.alt});
    EXPECT_LT((cam.pixel_ray(50, 30) - want).norm(), 1e-12)
        << p.az << " " << p.alt << " " << p.roll;
    EXPECT_LT((cam.optical_axis() - want).norm(), 1e-12);
  }
}

TEST(ViewCamera, RightIsIncreasingAzimuthUpIsIncreasingAltitude) {
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{40, 10}, 0}, 60.0, 101, 101);
  const Direction centre = from_unit(cam.pixel_ray(50, 50));
  const Direction right = from_unit(cam.pixel_ray(80, 50));
  const Direction up = from_unit(cam.pixel_ray(50, 20));  // smaller row index is higher
  EXPECT_GT(right.azimuth_deg, centre.azimuth_deg + 5.0);
  EXPECT_GT(up.altitude_deg, centre.altitude_deg + 5.0);
  EXPECT_NEAR(up.azimuth_deg, centre.azimuth_deg, 1e-9);
}

TEST(ViewCamera, PositiveRollTurnsTheImageClockwise) {
  // Clockwise by 90 degrees: what was above the centre appears right of it, what was right of it
  // appears below.
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 0}, 90.0}, 90.0, 100, 100);
  const auto above = cam.project(to_unit({0, 10}));
  const auto right = cam.project(to_unit({10, 0}));
  ASSERT_TRUE(above && right);
  EXPECT_GT(above->x(), 55.0);
  EXPECT_NEAR(above->y(), 50.0, 1e-9);
  EXPECT_NEAR(right->x(), 50.0, 1e-9);
  EXPECT_GT(right->y(), 55.0);
  // A small roll: the point above moves right (clockwise), not left.
  const ViewCamera small = ViewCamera::from_horizontal_fov({{0, 0}, 10.0}, 90.0, 100, 100);
  EXPECT_GT(small.project(to_unit({0, 20}))->x(), 50.0);
}

TEST(ViewCamera, HorizontalFovSpansTheImageWidth) {
  for (double fov : {30.0, 90.0, 120.0}) {
    const ViewCamera cam = ViewCamera::from_horizontal_fov({{20, -30}, 15}, fov, 640, 360);
    const double a = angle_between(cam.ray(0.0, 180.0), cam.ray(640.0, 180.0));
    EXPECT_NEAR(a * kRadToDeg, fov, 1e-9);
    EXPECT_DOUBLE_EQ(cam.fx(), cam.fy());
  }
}

TEST(ViewCamera, AsymmetricFovPutsTheOpticalCentreOffCentre) {
  const FovAngles fov{-0.9, 0.5, 0.7, -0.6};
  const ViewCamera cam = ViewCamera::from_fov_angles({{0, 0}, 0}, fov, 400, 300);
  const Eigen::Vector3d axis = cam.optical_axis();
  // The principal point projects the optical axis.
  const auto pp = cam.project(axis);
  ASSERT_TRUE(pp);
  EXPECT_NEAR(pp->x(), cam.cx(), 1e-9);
  EXPECT_NEAR(pp->y(), cam.cy(), 1e-9);
  EXPECT_GT(cam.cx(), 200.0);  // more field to the left than to the right
  // Edges: horizontal angle at the left/right edge, vertical at top/bottom (looking at az 0).
  const Direction left = from_unit(cam.ray(0.0, cam.cy()));
  const Direction right = from_unit(cam.ray(400.0, cam.cy()));
  const Direction top = from_unit(cam.ray(cam.cx(), 0.0));
  const Direction bottom = from_unit(cam.ray(cam.cx(), 300.0));
  EXPECT_NEAR(left.azimuth_deg, fov.angle_left * kRadToDeg, 1e-9);
  EXPECT_NEAR(right.azimuth_deg, fov.angle_right * kRadToDeg, 1e-9);
  EXPECT_NEAR(top.altitude_deg, fov.angle_up * kRadToDeg, 1e-9);
  EXPECT_NEAR(bottom.altitude_deg, fov.angle_down * kRadToDeg, 1e-9);
}

TEST(ViewCamera, ProjectionRoundTrip) {
  const ViewCamera cams[] = {
      ViewCamera::from_horizontal_fov({{-120, 35}, 20}, 100.0, 320, 200),
      ViewCamera::from_fov_angles({{170, -70}, -40}, {-0.8, 0.6, 0.75, -0.9}, 256, 256),
  };
  for (const auto& cam : cams) {
    for (double y = 0.0; y <= cam.height(); y += 13.7) {
      for (double x = 0.0; x <= cam.width(); x += 17.3) {
        const auto back = cam.project(cam.ray(x, y));
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->x(), x, 1e-9);
        EXPECT_NEAR(back->y(), y, 1e-9);
      }
    }
    EXPECT_FALSE(cam.project(-cam.optical_axis()));
  }
}

TEST(ViewCamera, MarginKeepsTheRays) {
  const ViewCamera cam =
      ViewCamera::from_fov_angles({{30, 5}, 10}, {-0.8, 0.6, 0.75, -0.9}, 64, 48);
  const ViewCamera wide = cam.with_margin(7);
  EXPECT_EQ(wide.width(), 78);
  EXPECT_EQ(wide.height(), 62);
  EXPECT_LT((wide.pixel_ray(7 + 3, 7 + 40) - cam.pixel_ray(3, 40)).norm(), 1e-15);
  EXPECT_LT((wide.optical_axis() - cam.optical_axis()).norm(), 1e-15);
}

TEST(ViewCamera, RejectsBadInput) {
  EXPECT_THROW(ViewCamera::from_horizontal_fov({}, 0.0, 10, 10), std::invalid_argument);
  EXPECT_THROW(ViewCamera::from_horizontal_fov({}, 180.0, 10, 10), std::invalid_argument);
  EXPECT_THROW(ViewCamera::from_horizontal_fov({}, 90.0, 0, 10), std::invalid_argument);
  EXPECT_THROW(ViewCamera::from_fov_angles({}, {0.5, -0.5, 0.5, -0.5}, 10, 10),
               std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
