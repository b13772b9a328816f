/// @file
/// @brief Why Chordal is the default: layouts where the paper's geodesic distance makes the
/// projected kernel indefinite or singular, while the chordal distance stays definite.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "effects/rbf_interpolator.h"
#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

std::vector<Keyframe> layout(int n, std::uint64_t seed, std::int64_t frames) {
  std::mt19937_64 rng(seed);
  std::vector<Keyframe> k;
  for (int i = 0; i < n; ++i) k.push_back(test::random_keyframe(rng, 1, 0, frames));
  return k;
}

/// Eigenvalues of Q2^T A Q2 (the kernel projected onto the null space of P^T), divided by the
/// largest magnitude. For alpha < 2 a well-posed kernel makes them all negative.
Eigen::VectorXd projected_eigenvalues(const std::vector<Keyframe>& k, double alpha,
                                      AngularDistance dist) {
  const RbfPoints pts = merge_keyframes(k, 1);
  InterpolationSettings s;
  s.exponent = alpha;
  s.distance = dist;
  const RbfKernel kernel = RbfKernel::from(s, 24.0);
  const Eigen::MatrixXd q = projected_kernel(kernel_matrix(pts, kernel),
                                             polynomial_matrix(pts, select_polynomial_basis(pts)));
  const Eigen::VectorXd e = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(q).eigenvalues();
  return e / e.cwiseAbs().maxCoeff();
}

const struct {
  const char* what;
  int n;
  std::uint64_t seed;
  std::int64_t frames;
  double alpha;
} kLayouts[] = {
    {"still, alpha 1.5 (geodesic^alpha is not CND for alpha > 1)", 6, 4, 0, 1.5},
    {"still, alpha 1.5, 12 keyframes", 12, 1, 0, 1.5},
    {"frames 0..3, alpha 1 (geodesic mixed with time)", 30, 1, 3, 1.0},
    {"frames 0..3, alpha 1, another layout", 30, 2, 3, 1.0},
};

TEST(RbfGeodesic, GeodesicIsIndefiniteWhereChordalIsDefinite) {
  for (const auto& l : kLayouts) {
    const auto k = layout(l.n, l.seed, l.frames);
    const Eigen::VectorXd geo = projected_eigenvalues(k, l.alpha, AngularDistance::Geodesic);
    const Eigen::VectorXd cho = projected_eigenvalues(k, l.alpha, AngularDistance::Chordal);
    EXPECT_GT(geo.maxCoeff(), 1e-3) << l.what << ": geodesic has a positive eigenvalue";
    EXPECT_LT(cho.maxCoeff(), -1e-6) << l.what << ": chordal is negative definite";
    // The solver notices: Cholesky fails for geodesic and the LU fallback still reproduces.
    InterpolationSettings s;
    s.exponent = l.alpha;
    s.distance = AngularDistance::Geodesic;
    const RbfInterpolator g(k, 1, s, 24.0);
    EXPECT_NE(g.diagnostics().method, RbfSolveMethod::NullSpaceCholesky) << l.what;
    s.distance = AngularDistance::Chordal;
    EXPECT_EQ(RbfInterpolator(k, 1, s, 24.0).diagnostics().method,
              RbfSolveMethod::NullSpaceCholesky)
        << l.what;
  }
}

TEST(RbfGeodesic, AnExponentBetweenOneAndOneAndAHalfMakesGeodesicSingular) {
  // At alpha = 1 the geodesic kernel of a still is definite; at 1.5 it is not (first layout).
  // An eigenvalue crosses zero in between: there the geodesic system is exactly singular.
  const auto k = layout(6, 4, 0);
  auto top = [&](double a) {
    return projected_eigenvalues(k, a, AngularDistance::Geodesic).maxCoeff();
  };
  double lo = 1.0, hi = 1.5;
  ASSERT_LT(top(lo), 0.0);
  ASSERT_GT(top(hi), 0.0);
  for (int i = 0; i < 60; ++i) ((top(0.5 * (lo + hi)) < 0.0) ? lo : hi) = 0.5 * (lo + hi);
  const double alpha_star = 0.5 * (lo + hi);
  EXPECT_LT(std::abs(top(alpha_star)), 1e-9) << "singular at alpha " << alpha_star;
  EXPECT_LT(projected_eigenvalues(k, alpha_star, AngularDistance::Chordal).maxCoeff(), -1e-3);
  // Even there the solver returns finite values.
  InterpolationSettings s;
  s.exponent = alpha_star;
  s.distance = AngularDistance::Geodesic;
  const RbfInterpolator g(k, 1, s, 24.0);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 50; ++i) EXPECT_TRUE(g.evaluate(test::random_direction(rng), 0).allFinite());
}

TEST(RbfGeodesic, ChordIsWithinOnePercentOfTheAngleBelow25Degrees) {
  for (double deg = 0.5; deg <= 25.0; deg += 0.5) {
    const double th = deg * kDegToRad;
    EXPECT_LT((th - 2 * std::sin(th / 2)) / th, 0.01) << deg;
  }
  const double th = 26.0 * kDegToRad;
  EXPECT_GT((th - 2 * std::sin(th / 2)) / th, 0.0085);
}

}  // namespace
}  // namespace vdfx::effects
