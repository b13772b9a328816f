/// @file
/// @brief Eye views: poses, projection against an independent frustum, optical centre on the
/// off-centre headset, mirror symmetry, and the Direction-based camera description.
#include "xr/headset/eye_views.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace vdfx::xr {
namespace {

Pose turned_head() {
  Pose head;
  head.orientation = glm::normalize(glm::angleAxis(0.7, glm::dvec3(0, 1, 0)) *
                                    glm::angleAxis(-0.3, glm::dvec3(1, 0, 0)) *
                                    glm::angleAxis(0.2, glm::dvec3(0, 0, 1)));
  head.position = {0.1, 1.6, -0.2};
  return head;
}

TEST(EyeViews, ProjectionMatchesAnIndependentFrustum) {
  const FovDeg fovs[] = {{-52, 47, 53, -53}, {-60, 30, 45, -35}, {-40, 40, 40, -40}};
  for (const FovDeg& fov : fovs) {
    const double n = 0.05, f = 100.0;
    const effects::TanRect t = fov.tangents();
    const glm::dmat4 peer = glm::frustumRH_NO(n * t.left, n * t.right, n * t.down, n * t.up, n, f);
    const glm::dmat4 ours = projection_from_fov(fov, n, f);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(ours[c][r], peer[c][r], 1e-12) << c << r;
    }
    const glm::dmat4 peer01 =
        glm::frustumRH_ZO(n * t.left, n * t.right, n * t.down, n * t.up, n, f);
    const glm::dmat4 ours01 = projection_from_fov(fov, n, f, ClipDepth::ZeroToOne);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(ours01[c][r], peer01[c][r], 1e-12) << c << r;
    }
    // Frustum edges land on the NDC edges; infinite far maps far points towards +1.
    const glm::dvec4 corner = ours * glm::dvec4(2.0 * t.right, 2.0 * t.up, -2.0, 1.0);
    EXPECT_NEAR(corner.x / corner.w, 1.0, 1e-12);
    EXPECT_NEAR(corner.y / corner.w, 1.0, 1e-12);
    const glm::dvec4 far = projection_from_fov(fov, n, 0.0) * glm::dvec4(0, 0, -1e9, 1);
    EXPECT_NEAR(far.z / far.w, 1.0, 1e-9);
  }
}

TEST(EyeViews, EyesSitHalfAnIpdEitherSideAlongHeadX) {
  const HmdProfile p = load_hmd_profile("generic90");
  const Pose head = turned_head();
  const auto views = locate_eye_views(head, p);
  const glm::dvec3 head_x = head.orientation * glm::dvec3(1, 0, 0);
  const glm::dvec3 l = views[0].pose.position, r = views[1].pose.position;
  EXPECT_NEAR(glm::length(r - l), p.ipd_m, 1e-12);
  EXPECT_NEAR(glm::dot(r - l, head_x), p.ipd_m, 1e-12);
  EXPECT_NEAR(glm::length(0.5 * (l + r) - head.position), 0.0, 1e-12);
  // The view matrix takes the eye to the origin, looking down -z.
  const glm::dvec4 eye_in_view = views[0].view * glm::dvec4(l, 1.0);
  EXPECT_NEAR(glm::length(glm::dvec3(eye_in_view)), 0.0, 1e-12);
  const glm::dvec3 fwd = head.orientation * glm::dvec3(0, 0, -1);
  const glm::dvec4 ahead = views[0].view * glm::dvec4(l + fwd, 1.0);
  EXPECT_NEAR(ahead.z, -1.0, 1e-12);
}

TEST(EyeViews, OpticalCentreOfTheOffCentreHeadset) {
  const HmdProfile p = load_hmd_profile("offcentre");
  const Pose head = turned_head();
  const auto views = locate_eye_views(head, p);
  std::array<glm::dvec2, 2> px;
  for (const Eye e : kEyes) {
    const EyeView& v = views[static_cast<int>(e)];
    px[static_cast<int>(e)] = optical_centre_px(v, head);
    // Expected from the FOV alone: the point 10 m ahead seen from an eye IPD/2 to the side has
    // tangent -+ (IPD/2)/10 horizontally and 0 vertically.
    const effects::TanRect t = p.eye(e).fov.tangents();
    const double tx = (e == Eye::Left ? 0.5 : -0.5) * p.ipd_m / 10.0;
    const double want_x = (tx - t.left) / (t.right - t.left) * v.width;
    const double want_y = t.up / (t.up - t.down) * v.height;
    EXPECT_NEAR(px[static_cast<int>(e)].x, want_x, 1e-6) << eye_name(e);
    EXPECT_NEAR(px[static_cast<int>(e)].y, want_y, 1e-6) << eye_name(e);
    // Far from the screen centre (the lens centre is at 75 % / 25 % across).
    EXPECT_GT(std::abs(px[static_cast<int>(e)].x - 0.5 * v.width), 0.2 * v.width);
    EXPECT_GT(std::abs(px[static_cast<int>(e)].y - 0.5 * v.height), 0.05 * v.height);
    // Within the parallax of 10 m of the lens centre the profile states.
    EXPECT_NEAR(px[static_cast<int>(e)].x / v.width, p.eye(e).lens_centre[0], 1e-2);
  }
  // Mirror images of each other.
  EXPECT_NEAR(px[0].x, views[1].width - px[1].x, 1e-6);
  EXPECT_NEAR(px[0].y, px[1].y, 1e-9);
  EXPECT_LT(px[1].x, 0.5 * views[1].width);
}

TEST(EyeViews, CameraDescriptionReproducesTheHeadRotation) {
  const HmdProfile p = load_hmd_profile("offcentre");
  const Pose heads[] = {Pose{}, turned_head()};
  for (const Pose& head : heads) {
    for (const Eye e : kEyes) {
      const EyeCamera cam = eye_camera(head, p, e);
      const glm::dmat3 want = glm::mat3_cast(head.orientation);
      const glm::dmat3 got = camera_rotation(cam.look, cam.roll_deg);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::length(got[c] - want[c]), 0.0, 1e-12) << c;
      EXPECT_NEAR(cam.angle_left, p.eye(e).fov.angle_left * effects::kDegToRad, 1e-15);
      EXPECT_EQ(cam.width, p.eye(e).width);
    }
  }
  // A head looking 30 degrees right and 10 up, rolled 15 degrees clockwise (as the image turns).
  Pose head;
  head.orientation = glm::quat_cast(camera_rotation({30.0, 10.0}, 15.0));
  const EyeCamera cam = eye_camera(head, p, Eye::Left);
  EXPECT_NEAR(cam.look.azimuth_deg, 30.0, 1e-9);
  EXPECT_NEAR(cam.look.altitude_deg, 10.0, 1e-9);
  EXPECT_NEAR(cam.roll_deg, 15.0, 1e-9);
  // Azimuth +90 looks along +x (OpenXR axes, contract).
  const glm::dvec3 f = camera_rotation({90.0, 0.0}, 0.0) * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(f.x, 1.0, 1e-15);
}

}  // namespace
}  // namespace vdfx::xr
