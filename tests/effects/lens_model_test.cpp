/// @file
/// @brief Lens model: forward/inverse agreement, closed-form error, monotonic limit, LCA.
#include "effects/lens_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vdfx::effects {
namespace {

/// Coefficient sets: the bundled profiles (xr/headset/profiles/*.json, also checked by the xr tests
/// on the loaded files), both Cardboard viewers and lenses whose forward function folds. r_d_use:
/// the largest normalised panel radius in use (the profile's panel corner), where known.
const struct {
  const char* name;
  double c1, c2;
  double r_d_use;
} kLenses[] = {
    {"generic90", 0.22, 0.24, 1.025},      {"cardboard-v1", 0.441, 0.156, 1.19},
    {"cardboard-v2", 0.34, 0.55, 1.19},    {"offcentre", 0.10, 0.05, 1.0},
    {"identity", 0.0, 0.0, 2.0},           {"barrel c1<0", -0.25, 0.0, 0.0},
    {"c1<0 c2<0", -0.1, -0.05, 0.0},       {"c1>0 c2<0", 0.3, -0.08, 0.0},
    {"c1<0 c2>0 folding", -0.6, 0.1, 0.0}, {"c1<0 c2>0 monotonic", -0.25, 0.05, 1.0},
};

TEST(LensModel, ForwardAndNewtonInverseAgreeInsideTheValidRadius) {
  for (const auto& row : kLenses) {
    const LensModel lens({row.c1, row.c2, 1.0, {1, 1, 1}});
    const double r_top = std::min(0.999 * lens.max_undistorted_radius(), 3.0);
    for (int k = 0; k <= 2000; ++k) {
      const double r_u = r_top * k / 2000.0;
      const double r_d = lens.forward(r_u);
      const InverseResult inv = lens.inverse_newton(r_d);
      ASSERT_TRUE(inv.valid) << row.name << " r_u " << r_u;
      EXPECT_NEAR(inv.r_u, r_u, 1e-6) << row.name << " r_u " << r_u;
      EXPECT_NEAR(lens.forward(inv.r_u), r_d, 1e-12 * std::max(1.0, r_d)) << row.name;
      EXPECT_LT(inv.iterations, LensModel::kMaxIterations) << row.name << " hit the cap at " << r_u;
    }
  }
}

TEST(LensModel, ClosedFormErrorIsBoundedByTheMeasuredFigure) {
  // Measured (docs/lens.md, "Inverse accuracy") with ~1.5x margin: the closed form is an
  // approximation whose error grows fast with radius; the test guards against it getting worse.
  const struct {
    const char* name;
    double bound;
  } kBounds[] = {{"generic90", 1.3e-2}, {"cardboard-v1", 9e-2}, {"cardboard-v2", 0.2},
                 {"offcentre", 4e-4},   {"identity", 1e-14},    {"c1<0 c2>0 monotonic", 0.15}};
  for (const auto& b : kBounds) {
    const auto* row = std::find_if(std::begin(kLenses), std::end(kLenses),
                                   [&](const auto& r) { return std::string(r.name) == b.name; });
    ASSERT_NE(row, std::end(kLenses));
    const LensModel lens({row->c1, row->c2, 1.0, {1, 1, 1}});
    double worst = 0.0;
    for (int k = 0; k <= 4000; ++k) {
      const double r_d = row->r_d_use * k / 4000.0;
      const auto approx = lens.inverse_closed_form(r_d);
      const InverseResult exact = lens.inverse_newton(r_d);
      ASSERT_TRUE(approx && exact.valid) << b.name << " r_d " << r_d;
      worst = std::max(worst, std::abs(*approx - exact.r_u));
    }
    std::printf("closed-form inverse, %-20s max |error| over r_d in [0, %.2f]: %.3e\n", b.name,
                row->r_d_use, worst);
    EXPECT_LE(worst, b.bound) << b.name;
    if (row->c1 != 0.0) {
      EXPECT_GT(worst, 0.0) << b.name << ": an approximation, not exact";
    }
  }
}

TEST(LensModel, MonotonicLimitIsTheFirstRootOfTheDerivative) {
  for (const auto& row : kLenses) {
    const LensModel lens({row.c1, row.c2, 1.0, {1, 1, 1}});
    const double r_max = lens.max_undistorted_radius();
    // With both coefficients >= 0, or a negative discriminant, f' never reaches 0.
    const bool folds = (row.c1 < 0.0 && row.c2 <= 0.0) || row.c2 < 0.0 ||
                       (row.c1 < 0.0 && 9 * row.c1 * row.c1 - 20 * row.c2 >= 0.0);
    SCOPED_TRACE(row.name);
    ASSERT_EQ(std::isfinite(r_max), folds);
    if (!folds) {
      EXPECT_TRUE(lens.inverse_newton(1e3).valid);
      continue;
    }
    EXPECT_NEAR(lens.derivative(r_max), 0.0, 1e-12);
    for (int k = 0; k < 100; ++k) EXPECT_GT(lens.derivative(r_max * k / 100.0), 0.0);
    // A maximum of f: anything beyond it would fold back.
    EXPECT_LT(lens.forward(r_max * 1.01), lens.max_distorted_radius());
    EXPECT_DOUBLE_EQ(lens.forward(r_max), lens.max_distorted_radius());
    // Nothing at or beyond the limit has an inverse, with either method...
    for (const double over : {1.0, 1.0 + 1e-12, 1.01, 1.5, 10.0}) {
      const double r_d = lens.max_distorted_radius() * over;
      EXPECT_FALSE(lens.inverse_newton(r_d).valid) << over;
      EXPECT_FALSE(lens.inverse_closed_form(r_d).has_value()) << over;
    }
    // ...nor maps forward from beyond it; just inside it the solve still converges within the cap.
    EXPECT_FALSE(lens.view_to_panel({r_max * 1.001, 0.0}, 1).has_value());
    EXPECT_TRUE(lens.view_to_panel({r_max * 0.999, 0.0}, 1).has_value());
    const InverseResult near = lens.inverse_newton(lens.max_distorted_radius() * (1 - 1e-9));
    ASSERT_TRUE(near.valid);
    EXPECT_LE(near.iterations, LensModel::kMaxIterations);
    EXPECT_NEAR(near.r_u, r_max, 1e-3 * r_max);
  }
}

TEST(LensModel, RejectsBadRadiiAndParameters) {
  const LensModel lens({0.22, 0.24, 1.0, {1, 1, 1}});
  EXPECT_FALSE(lens.inverse_newton(-0.1).valid);
  EXPECT_FALSE(lens.inverse_newton(std::numeric_limits<double>::quiet_NaN()).valid);
  EXPECT_THROW(LensModel({0.1, 0.0, 0.0, {1, 1, 1}}), std::invalid_argument);
  EXPECT_THROW(LensModel({0.1, 0.0, 1.0, {1, -1, 1}}), std::invalid_argument);
  EXPECT_THROW(LensModel({std::nan(""), 0.0, 1.0, {1, 1, 1}}), std::invalid_argument);
}

TEST(LensModel, NormalisationRadiusScalesTheModel) {
  // Same lens at twice the radius unit: the tangent-plane map scales, the shape does not change.
  const LensModel unit({0.3, 0.1, 1.0, {1, 1, 1}});
  const LensModel twice({0.3, 0.1, 2.0, {1, 1, 1}});
  const Eigen::Vector2d t(0.3, -0.4);
  EXPECT_LT((*twice.view_to_panel(2.0 * t, 1) - 2.0 * *unit.view_to_panel(t, 1)).norm(), 1e-14);
}

const struct {
  const char* name;
  LensParams params;
} kLcaLenses[] = {
    {"no distortion, DK2 LCA", {0.0, 0.0, 1.0, {0.985, 1.0, 1.015}}},
    {"generic90", {0.22, 0.24, 1.8, {0.985, 1.0, 1.015}}},
    {"offcentre", {0.10, 0.05, 2.0, {0.99, 1.0, 1.01}}},
};

/// Through-the-lens colour fringe at image point u: the spread of the source points that the
/// three channels seen at u were sampled from. (The eye looks at u; channel c comes from panel
/// point view_to_panel(u, c); the pre-distortion drew there source_for_panel(., c).)
double fringe(const LensModel& lens, const Eigen::Vector2d& u, bool correction,
              std::array<Eigen::Vector2d, 3>* src_out = nullptr) {
  std::array<Eigen::Vector2d, 3> src;
  for (int c = 0; c < 3; ++c) {
    const auto panel = lens.view_to_panel(u, c);
    src[c] = *lens.source_for_panel(*panel, c, correction, InverseMethod::Newton);
  }
  if (src_out) *src_out = src;
  return std::max({(src[0] - src[1]).norm(), (src[2] - src[1]).norm(), (src[0] - src[2]).norm()});
}

TEST(LensModel, InverseLcaBringsTheChannelsTogether) {
  for (const auto& row : kLcaLenses) {
    const LensModel lens(row.params);
    for (const Eigen::Vector2d& u : {Eigen::Vector2d(0.2, 0.1), Eigen::Vector2d(-0.7, 0.5),
                                     Eigen::Vector2d(1.0, -0.9), Eigen::Vector2d(0.0, 0.0)}) {
      EXPECT_LT(fringe(lens, u, true), 1e-6) << row.name << " u " << u.transpose();
    }
  }
}

TEST(LensModel, WithoutCorrectionTheChannelsSpreadByTheExpectedAmount) {
  // No distortion: channel c seen at u was drawn from source k_c u, an exact spread.
  const LensModel flat(kLcaLenses[0].params);
  const Eigen::Vector2d u(0.6, -0.8);  // |u| = 1
  std::array<Eigen::Vector2d, 3> src;
  EXPECT_NEAR(fringe(flat, u, false, &src), 0.030, 1e-12);
  EXPECT_LT((src[0] - 0.985 * u).norm(), 1e-12);
  EXPECT_LT((src[2] - 1.015 * u).norm(), 1e-12);
  // With distortion: to first order the source radius is r + (k_c - 1) f(r) / f'(r).
  for (const auto& row : kLcaLenses) {
    const LensModel lens(row.params);
    const double R = row.params.radius;
    const Eigen::Vector2d v = Eigen::Vector2d(0.6, 0.8) * 0.5 * R;
    const double r = 0.5;
    const double expected = (row.params.lca_scale[2] - row.params.lca_scale[0]) * lens.forward(r) /
                            lens.derivative(r) * R;
    EXPECT_NEAR(fringe(lens, v, false), expected, 0.05 * expected) << row.name;
  }
}

TEST(EyeLens, PanelSourceUvFollowsTheLensAndTheFov) {
  EyeLens eye;
  eye.width = 1000;
  eye.height = 800;
  eye.fov = {-1.5, 0.5, 0.8, -0.8};
  eye.lens = LensModel({0.22, 0.24, 1.8, {0.985, 1.0, 1.015}});
  // The lens centre is where the optical axis is in the image: 75 % across, half-way down.
  EXPECT_LT((eye.centre_pixel() - Eigen::Vector2d(750, 400)).norm(), 1e-12);
  const ChannelSamples centre = panel_source_uv(eye, eye.centre_pixel(), true);
  for (int c = 0; c < 3; ++c) {
    ASSERT_TRUE(centre.valid[c]);
    EXPECT_LT((centre.uv[c] - Eigen::Vector2d(0.75, 0.5)).norm(), 1e-12);
  }
  // A point off-axis: the source lies on the same ray from the centre, nearer to it (c > 0),
  // and the through-the-lens forward map takes it back to the panel point.
  const Eigen::Vector2d px(100, 150);
  const ChannelSamples s = panel_source_uv(eye, px, true);
  for (int c = 0; c < 3; ++c) {
    ASSERT_TRUE(s.valid[c]);
    const Eigen::Vector2d src_px = s.uv[c].cwiseProduct(Eigen::Vector2d(1000, 800));
    const Eigen::Vector2d a = px - eye.centre_pixel(), b = src_px - eye.centre_pixel();
    EXPECT_NEAR(a.x() * b.y() - a.y() * b.x(), 0.0, 1e-6 * a.norm() * b.norm());
    EXPECT_LT(b.norm(), a.norm());
    EXPECT_LT((*through_lens_panel_px(eye, src_px, c) - px).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace vdfx::effects
