/// @file
/// @brief Flare geometry (the guide's formulas for both styles), the ring line, constant angular
/// size, and the fade (zero beyond fade + ramp/2, full inside fade - ramp/2, monotonic between).
#include "effects/flare_layout.h"

#include <gtest/gtest.h>

#include <cmath>

#include "effects/flare_render.h"
#include "effects/view_camera.h"
#include "tests/image_centroid.h"

namespace vdfx::effects {
namespace {

HeadPose head_looking_at(const Direction& d, const Eigen::Vector3d& position = {0.1, 1.6, -0.2}) {
  HeadPose h;
  h.position = position;
  h.orientation = pose_rotation({d, 7.0});  // some roll: the layout must not depend on it
  return h;
}

/// Distance of point p from the line through a and b.
double off_line(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = (b - a).normalized();
  return ((p - a) - (p - a).dot(u) * u).norm();
}

TEST(FlareLayout, DirectionalStyleFollowsTheGuidesFormulas) {
  const HeadPose head = head_looking_at({10.0, 5.0});
  const Eigen::Vector3d l = to_unit({18.0, 9.0});
  const FlareSettings s = default_flare_settings(FlareStyle::Directional);
  const auto layout = layout_flare(FlareStyle::Directional, s, head, l, 1.0);
  ASSERT_TRUE(layout);
  const Eigen::Vector3d& A = head.position;
  const Eigen::Vector3d g = head.forward();
  // C = A + D l; B = A + (D / g.l) g: both on the plane perpendicular to l at distance D.
  EXPECT_LT((layout->light_point - (A + 100.0 * l)).norm(), 1e-9);
  EXPECT_LT((layout->view_point - (A + (100.0 / g.dot(l)) * g)).norm(), 1e-9);
  EXPECT_NEAR((layout->view_point - A).dot(l), 100.0, 1e-9);
  EXPECT_LT((layout->normal - l).norm(), 1e-12);
  EXPECT_NEAR(layout->theta_deg, angle_between(g, l) * kRadToDeg, 1e-12);
}

TEST(FlareLayout, HeadsetStyleFollowsTheGuidesFormulas) {
  const HeadPose head = head_looking_at({-40.0, 20.0});
  const Eigen::Vector3d l = to_unit({-30.0, 24.0});
  const FlareSettings s = default_flare_settings(FlareStyle::Headset);
  EXPECT_EQ(s.plane_m, 0.05);
  const auto layout = layout_flare(FlareStyle::Headset, s, head, l, 2.0);
  ASSERT_TRUE(layout);
  const Eigen::Vector3d& A = head.position;
  const Eigen::Vector3d g = head.forward();
  // B = A + d g; C = A + (d / g.l) l: both on the plane perpendicular to g at distance d.
  EXPECT_LT((layout->view_point - (A + 0.05 * g)).norm(), 1e-12);
  EXPECT_LT((layout->light_point - (A + (0.05 / g.dot(l)) * l)).norm(), 1e-12);
  EXPECT_NEAR((layout->light_point - A).dot(g), 0.05, 1e-12);
  EXPECT_LT((layout->normal - g).norm(), 1e-12);
}

TEST(FlareLayout, GlareAtTheLightRingsOnTheLineThroughTheViewCentre) {
  for (const FlareStyle style : {FlareStyle::Headset, FlareStyle::Directional}) {
    const HeadPose head = head_looking_at({0.0, 0.0});
    FlareSettings s = default_flare_settings(style);
    s.rings = kMaxFlareRings;
    const auto layout = layout_flare(style, s, head, to_unit({8.0, 6.0}), 1.0);
    ASSERT_TRUE(layout);
    ASSERT_EQ(layout->elements.size(), 2u + kMaxFlareRings);
    const Eigen::Vector3d C = layout->light_point, B = layout->view_point;
    EXPECT_EQ(layout->elements[0].centre, C);
    EXPECT_EQ(layout->elements[1].centre, C);
    const double scale = (B - C).norm();
    for (int i = 0; i < kMaxFlareRings; ++i) {
      const FlareElement& e = layout->elements[static_cast<std::size_t>(2 + i)];
      EXPECT_EQ(e.shape, FlareShape::Ring);
      EXPECT_LT(off_line(e.centre, C, B), 1e-12 * layout->plane_distance);
      EXPECT_NEAR((e.centre - C).norm() / scale, ring_table()[static_cast<std::size_t>(i)].s, 1e-9);
      // In the plane, and of constant angular size: radius / plane distance = tan(alpha).
      EXPECT_NEAR((e.centre - C).dot(layout->normal), 0.0, 1e-12 * layout->plane_distance);
      EXPECT_NEAR(
          e.radius / layout->plane_distance,
          std::tan(ring_table()[static_cast<std::size_t>(i)].angular_radius_deg * kDegToRad),
          1e-12);
    }
    // Some rings lie before the view centre, some beyond it.
    bool before = false, beyond = false;
    for (const RingSpec& r : ring_table().first(6)) {
      before = before || r.s < 1.0;
      beyond = beyond || r.s > 1.0;
    }
    EXPECT_TRUE(before && beyond);
  }
}

TEST(FlareLayout, RingsSpreadAsTheGazeMovesAwayFromTheLight) {
  const Eigen::Vector3d l = to_unit({0.0, 0.0});
  double previous = 0.0;
  for (double gaze_az : {1.0, 4.0, 8.0, 12.0}) {
    const auto layout = layout_flare(FlareStyle::Directional, {},
                                     head_looking_at({gaze_az, 0.0}, {0, 0, 0}), l, 1.0);
    ASSERT_TRUE(layout);
    // Angular spread (seen from the head) between the first and the last ring.
    const Eigen::Vector3d a = layout->elements[2].centre, b = layout->elements.back().centre;
    const double spread = angle_between(a, b);
    EXPECT_GT(spread, previous) << gaze_az;
    previous = spread;
  }
}

TEST(FlareLayout, FadeIsZeroBeyondFullInsideMonotonicBetween) {
  const double fade = 15.0, ramp = 5.0;
  EXPECT_EQ(flare_fade(0.0, fade, ramp), 1.0);
  EXPECT_EQ(flare_fade(fade - ramp / 2, fade, ramp), 1.0);
  EXPECT_EQ(flare_fade(fade + ramp / 2, fade, ramp), 0.0);
  EXPECT_EQ(flare_fade(40.0, fade, ramp), 0.0);
  EXPECT_NEAR(flare_fade(fade, fade, ramp), 0.5, 1e-15);
  // ramp 0: a hard edge.
  EXPECT_EQ(flare_fade(fade, fade, 0.0), 1.0);
  EXPECT_EQ(flare_fade(std::nextafter(fade, 90.0), fade, 0.0), 0.0);

  // The drawn flare: its light at the glare centre, as the gaze turns away from the light.
  FlareSettings s;
  s.rings = 0;
  const Eigen::Vector3d l = to_unit({0.0, 0.0});
  const Eigen::Vector3d full = flare_at_ray(
      *layout_flare(FlareStyle::Directional, s, head_looking_at({1.0, 0.0}, {0, 0, 0}), l, 1.0),
      Eigen::Vector3d::Zero(), l);
  ASSERT_GT(full.sum(), 0.5);
  double previous = full.sum();
  for (double theta = 0.0; theta <= 30.0; theta += 0.125) {
    const HeadPose head = head_looking_at({theta, 0.0}, {0, 0, 0});
    const auto layout = layout_flare(FlareStyle::Directional, s, head, l, 1.0);
    const double drawn = layout ? flare_at_ray(*layout, Eigen::Vector3d::Zero(), l).sum() : 0.0;
    if (theta >= fade + ramp / 2) {
      EXPECT_FALSE(layout) << theta;
      EXPECT_EQ(drawn, 0.0) << theta;
    } else if (theta <= fade - ramp / 2) {
      EXPECT_NEAR(drawn, full.sum(), 1e-12) << theta;
    } else {
      EXPECT_LT(drawn, full.sum()) << theta;
      EXPECT_GT(drawn, 0.0) << theta;
    }
    EXPECT_LE(drawn, previous + 1e-15) << theta;
    previous = drawn;
  }
}

TEST(FlareLayout, NothingWithoutIntensityOrWithTheLightBehind) {
  const HeadPose head = head_looking_at({0.0, 0.0});
  EXPECT_FALSE(layout_flare(FlareStyle::Directional, {}, head, to_unit({1.0, 0.0}), 0.0));
  FlareSettings wide;
  wide.fade_deg = 80.0;
  wide.ramp_deg = 10.0;
  EXPECT_FALSE(layout_flare(FlareStyle::Headset, wide, head, to_unit({100.0, 0.0}), 4.0));
  EXPECT_TRUE(layout_flare(FlareStyle::Headset, wide, head, to_unit({70.0, 0.0}), 4.0));
}

TEST(FlareLayout, IntensityScalesEveryElement) {
  const HeadPose head = head_looking_at({3.0, 2.0});
  const auto one = layout_flare(FlareStyle::Directional, {}, head, to_unit({0.0, 0.0}), 1.0);
  const auto three = layout_flare(FlareStyle::Directional, {}, head, to_unit({0.0, 0.0}), 3.0);
  ASSERT_TRUE(one && three);
  for (std::size_t i = 0; i < one->elements.size(); ++i)
    EXPECT_LT((three->elements[i].colour - 3.0 * one->elements[i].colour).norm(), 1e-12);
}

TEST(FlareProfile, RingChannelsSitAtTheirOwnRadiiRedOutermost) {
  FlareElement ring{FlareShape::Ring, Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3d::Ones(), 0.06};
  // Each channel's rim peaks at (1 + chroma (1, 0, -1)) radii.
  const auto peak_of = [&](int c) {
    double best = 0.0, at = 0.0;
    for (double rho = 0.8; rho < 1.2; rho += 1e-4) {
      const double v = element_profile(ring, rho)[c];
      if (v > best) best = v, at = rho;
    }
    return at;
  };
  EXPECT_NEAR(peak_of(0), 1.06, 2e-4);
  EXPECT_NEAR(peak_of(1), 1.00, 2e-4);
  EXPECT_NEAR(peak_of(2), 0.94, 2e-4);
  // Compact support: exactly nothing at and beyond element_support.
  const double edge = element_support(ring);
  EXPECT_EQ(element_profile(ring, edge * (1.0 + 1e-12)).norm(), 0.0);
  EXPECT_GT(element_profile(ring, edge - 0.02).norm(), 0.0);
  FlareElement glow{FlareShape::Glow, Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3d::Ones(), 0.0};
  EXPECT_EQ(element_profile(glow, 0.0), Eigen::Vector3d::Ones());
  EXPECT_EQ(element_profile(glow, 1.0).norm(), 0.0);
  EXPECT_EQ(element_support(glow), 1.0);
}

TEST(FlareRender, GlareLandsOnTheLightsProjectionInEachEye) {
  // Directional flare: seen from an eye 3 cm off the head, the glare is where the light is (the
  // plane is 100 m away); headset flare: where the 5 cm point C projects, far off the light.
  const HeadPose head = head_looking_at({0.0, 0.0}, {0, 0, 0});
  const Eigen::Vector3d l = to_unit({6.0, 4.0});
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0.0, 0.0}, 7.0}, 90.0, 400, 300);
  for (const FlareStyle style : {FlareStyle::Directional, FlareStyle::Headset}) {
    FlareSettings s = default_flare_settings(style);
    s.rings = 0;
    const auto layout = layout_flare(style, s, head, l, 1.0);
    ASSERT_TRUE(layout);
    for (double ex : {-0.0315, 0.0315}) {
      const Eigen::Vector3d eye = head.orientation * Eigen::Vector3d(ex, 0, 0);
      cv::Mat img(300, 400, CV_32FC3, cv::Scalar::all(0));
      const FlareLayout one = *layout;
      add_flares(img, cam, eye, std::span<const FlareLayout>(&one, 1));
      cv::Mat g;
      cv::extractChannel(img, g, 1);
      const Eigen::Vector2d c = test_images::half_max_centroid(g);
      const Eigen::Vector3d target = style == FlareStyle::Directional
                                         ? Eigen::Vector3d(l)
                                         : Eigen::Vector3d(layout->light_point - eye);
      const auto expected = cam.project(target);
      ASSERT_TRUE(expected);
      EXPECT_NEAR(c.x(), expected->x(), 0.2) << static_cast<int>(style) << " eye " << ex;
      EXPECT_NEAR(c.y(), expected->y(), 0.2) << static_cast<int>(style) << " eye " << ex;
    }
  }
}

}  // namespace
}  // namespace vdfx::effects
