/// @file
/// @brief The pixel footprint: the analytic Jacobian against finite differences of the equirect
/// mapping (at the seam too), the taps' axis, count, spacing, level and weights, and their
/// continuity (a tap appears with weight 0).
#include "effects/pixel_footprint.h"

#include <gtest/gtest.h>

#include <cmath>

#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"

namespace vdfx::effects {
namespace {

// The Jacobian of (u, v) in texels from central differences of direction_to_uv.
Eigen::Matrix2d numeric_jacobian(const ViewCamera& cam, double x, double y, const TexelScale& t) {
  const double h = 1e-4;
  const auto uv = [&](double px, double py) { return direction_to_uv(cam.ray(px, py)); };
  const auto diff = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    double du = a.x() - b.x();
    du -= std::round(du);  // the short way round the seam
    Eigen::Vector2d out;
    out << du * t.per_turn / (2 * h), (a.y() - b.y()) * t.per_half_turn / (2 * h);
    return out;
  };
  Eigen::Matrix2d j;
  j.col(0) = diff(uv(x + h, y), uv(x - h, y));
  j.col(1) = diff(uv(x, y + h), uv(x, y - h));
  return j;
}

Eigen::Matrix2d analytic_jacobian(const ViewCamera& cam, double x, double y, const TexelScale& t) {
  const Eigen::Matrix3d& r = cam.camera_to_world();
  const Eigen::Vector2d tan = cam.tangent(x, y);
  const Eigen::Vector3d d = r * Eigen::Vector3d(tan.x(), tan.y(), -1.0);
  return equirect_jacobian(d, r.col(0) / cam.fx(), -r.col(1) / cam.fy(), t);
}

TEST(PixelFootprint, JacobianMatchesFiniteDifferences) {
  const TexelScale t{2048.0, 1024.0};
  const struct {
    ViewPose pose;
    double fov;
  } views[] = {
      {{{0, 0}, 0}, 90}, {{{180, 10}, 30}, 60}, {{{-45, 75}, -10}, 120}, {{{100, -88}, 0}, 40}};
  for (const auto& v : views) {
    const ViewCamera cam = ViewCamera::from_horizontal_fov(v.pose, v.fov, 64, 48);
    for (const auto& [x, y] : {std::pair{0.5, 0.5}, {31.5, 23.5}, {63.5, 10.5}, {12.5, 47.5}}) {
      const Eigen::Matrix2d a = analytic_jacobian(cam, x, y, t);
      const Eigen::Matrix2d n = numeric_jacobian(cam, x, y, t);
      EXPECT_LT((a - n).norm(), 1e-5 * (1.0 + a.norm())) << v.pose.look.azimuth_deg << " " << x;
    }
  }
}

TEST(PixelFootprint, IsotropicFootprintIsOneTapAtItsLevel) {
  for (double s : {0.25, 1.0, 3.0, 40.0}) {
    const Eigen::Matrix2d j = s * Eigen::Matrix2d::Identity();
    const FootprintTaps t = footprint_taps(j, 16.0, 1e6);
    EXPECT_EQ(t.half_count, 0) << s;
    EXPECT_DOUBLE_EQ(t.weight(0), 1.0);
    EXPECT_NEAR(t.lod, std::max(0.0, std::log2(s)), 1e-12) << s;
  }
}

TEST(PixelFootprint, AnisotropicFootprintTapsAlongItsMajorAxis) {
  // J = Rot(30 deg) diag(8, 2) Rot(-phi)^T: the screen direction phi is stretched 8x, the
  // perpendicular one 2x. r = 4: taps at k/4 pixels, k = -2..2, the outer two halved; level 1.
  const double phi = 0.7;
  Eigen::Matrix2d rot_tex, rot_screen;
  rot_tex << std::cos(0.5), -std::sin(0.5), std::sin(0.5), std::cos(0.5);
  rot_screen << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  const Eigen::Matrix2d j =
      rot_tex * Eigen::Vector2d(8.0, 2.0).asDiagonal() * rot_screen.transpose();
  const FootprintTaps t = footprint_taps(j, 16.0, 1e6);
  EXPECT_NEAR(std::abs(t.axis.dot(Eigen::Vector2d(std::cos(phi), std::sin(phi)))), 1.0, 1e-12);
  EXPECT_NEAR(t.spacing, 0.25, 1e-12);
  EXPECT_EQ(t.half_count, 2);
  EXPECT_NEAR(t.lod, 1.0, 1e-12);
  EXPECT_NEAR(t.weight(0), 0.25, 1e-12);
  EXPECT_NEAR(t.weight(1), 0.25, 1e-12);
  EXPECT_NEAR(t.weight(2), 0.125, 1e-12);
  EXPECT_NEAR(t.weight(-2), 0.125, 1e-12);
  // Beyond max_anisotropy the taps stop spreading and the level rises instead.
  const FootprintTaps capped = footprint_taps(j, 2.0, 1e6);
  EXPECT_NEAR(capped.spacing, 0.5, 1e-12);
  EXPECT_NEAR(capped.lod, 2.0, 1e-12);
  // A footprint longer than a turn is a turn.
  const Eigen::Matrix2d very_long =
      rot_tex * Eigen::Vector2d(8000.0, 2.0).asDiagonal() * rot_screen.transpose();
  const FootprintTaps turn = footprint_taps(very_long, 16.0, 512.0);
  EXPECT_NEAR(turn.lod, std::log2(512.0 / 16.0), 1e-12);
}

TEST(PixelFootprint, WeightsSumToOneAndChangeContinuously) {
  // Sweep the stretch through the points where a tap appears (r odd) and where r is capped.
  double prev_sum = 0.0;
  std::vector<double> prev;
  for (double stretch = 1.0; stretch <= 20.0; stretch += 1.0 / 64.0) {
    const Eigen::Matrix2d j = Eigen::Vector2d(2.0 * stretch, 2.0).asDiagonal();
    const FootprintTaps t = footprint_taps(j, 16.0, 1e6);
    std::vector<double> w(20, 0.0);
    double sum = 0.0;
    for (int k = -t.half_count; k <= t.half_count; ++k) {
      sum += t.weight(k);
      if (k >= 0) w[static_cast<std::size_t>(k)] = t.weight(k);
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << stretch;
    if (!prev.empty()) {
      for (std::size_t k = 0; k < w.size(); ++k)
        EXPECT_LT(std::abs(w[k] - prev[k]), 0.02) << "stretch " << stretch << " tap " << k;
    }
    prev = w;
    prev_sum = sum;
  }
  EXPECT_NEAR(prev_sum, 1.0, 1e-12);
}

TEST(PixelFootprint, FiniteOnThePoleAxis) {
  const TexelScale t{1024.0, 512.0};
  const Eigen::Vector3d up(0, 1, 0);
  const Eigen::Matrix2d j =
      equirect_jacobian(up, Eigen::Vector3d(1e-3, 0, 0), Eigen::Vector3d(0, 0, 1e-3), t);
  EXPECT_TRUE(j.allFinite());
  const FootprintTaps taps = footprint_taps(j, 16.0, t.per_turn);
  EXPECT_TRUE(std::isfinite(taps.lod));
  EXPECT_NEAR(taps.lod, std::log2(1024.0 / 16.0), 1e-9);
}

}  // namespace
}  // namespace vdfx::effects
