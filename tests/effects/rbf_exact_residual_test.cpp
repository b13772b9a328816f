/// @file
/// @brief The Dot2 residual: exact where double summation loses everything, and as accurate as a
/// long double reference on random systems.
#include "effects/rbf_exact_residual.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vdfx::effects {
namespace {

TEST(SaddleResidualDot2, RecoversWhatDoubleSummationCancelsAway) {
  // One row: f - (1e16 * 1 + 1 * 1 + (-1e16) * 1) - p c. In double, 1e16 + 1 rounds to 1e16 and
  // the row sums to 0; exactly it is f - 1. The products are exact, the sum is not.
  Eigen::MatrixXd a(3, 3);
  a << 1e16, 1.0, -1e16,  //
      1.0, 3.0, 0.0,      //
      -1e16, 0.0, 1e16;
  const Eigen::MatrixXd w = Eigen::MatrixXd::Ones(3, 1);
  Eigen::MatrixXd p(3, 1);
  p << 1.0, 1e-17, -1.0;  // g - P^T w = 0 - (1 + 1e-17 - 1) = -1e-17 exactly
  const Eigen::MatrixXd c = Eigen::MatrixXd::Constant(1, 1, 0.5);
  Eigen::MatrixXd f(3, 1);
  f << 2.0, 5.0, 0.0;
  const Eigen::MatrixXd g = Eigen::MatrixXd::Zero(1, 1);
  const Eigen::MatrixXd naive = f - a * w - p * c;
  EXPECT_EQ(naive(0, 0), 1.5);  // what double gives (the exact value is 0.5)
  Eigen::MatrixXd rf, rg;
  saddle_residual_dot2(a, p, f, g, w, c, rf, rg);
  EXPECT_EQ(rf(0, 0), 2.0 - 1.0 - 0.5);
  EXPECT_EQ(rf(1, 0), 5.0 - 4.0 - 0.5e-17);
  EXPECT_EQ(rf(2, 0), 0.0 - 0.0 + 0.5);
  EXPECT_EQ(rg(0, 0), -1e-17);
}

TEST(SaddleResidualDot2, MatchesALongDoubleReferenceOnCancellingSystems) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  for (int trial = 0; trial < 5; ++trial) {
    const int m = 40 + 17 * trial, r = 4, d = 2;
    Eigen::MatrixXd x = Eigen::MatrixXd::NullaryExpr(m, m, [&] { return n01(rng); });
    const Eigen::MatrixXd a = (x + x.transpose()) * 1e6;
    const Eigen::MatrixXd p = Eigen::MatrixXd::NullaryExpr(m, r, [&] { return n01(rng); });
    const Eigen::MatrixXd w = Eigen::MatrixXd::NullaryExpr(m, d, [&] { return n01(rng); });
    const Eigen::MatrixXd c = Eigen::MatrixXd::NullaryExpr(r, d, [&] { return n01(rng); });
    // f and g chosen so the residual nearly cancels: the double product plus a small offset.
    const Eigen::MatrixXd f = a * w + p * c + Eigen::MatrixXd::Constant(m, d, 1e-9);
    const Eigen::MatrixXd g = p.transpose() * w;
    Eigen::MatrixXd rf, rg;
    saddle_residual_dot2(a, p, f, g, w, c, rf, rg);
    for (int k = 0; k < d; ++k) {
      for (int i = 0; i < m; ++i) {
        long double ref = f(i, k), mag = std::abs(f(i, k));
        for (int j = 0; j < m; ++j) {
          ref -= static_cast<long double>(a(i, j)) * w(j, k);
          mag += std::abs(static_cast<long double>(a(i, j)) * w(j, k));
        }
        for (int q = 0; q < r; ++q) ref -= static_cast<long double>(p(i, q)) * c(q, k);
        // long double carries 64 bits: its own error is ~m 2^-64 mag; Dot2 is better still.
        ASSERT_NEAR(rf(i, k), static_cast<double>(ref),
                    static_cast<double>(4 * m * std::ldexp(mag, -64)) + 1e-30)
            << "trial " << trial << " row " << i;
      }
    }
  }
}

TEST(SaddleResidualDot2, ItsRoundingFloorIsTheLargestRowsTermsNormTimesTheUnitRoundoff) {
  // Row 0's terms: A w = (3, -4), P c = 12 -> sqrt(9 + 16 + 144) = 13; row 1's: (1, 1), 0.
  Eigen::MatrixXd a(2, 2);
  a << 3.0, -4.0,  //
      1.0, 1.0;
  const Eigen::MatrixXd w = Eigen::MatrixXd::Ones(2, 1);
  Eigen::MatrixXd p(2, 1);
  p << 6.0, 0.0;
  const Eigen::MatrixXd c = Eigen::MatrixXd::Constant(1, 1, 2.0);
  const Eigen::MatrixXd f = Eigen::MatrixXd::Constant(2, 1, 100.0);  // not a term of the floor
  Eigen::MatrixXd rf, rg;
  double floor = -1.0;
  saddle_residual_dot2(a, p, f, Eigen::MatrixXd::Zero(1, 1), w, c, rf, rg, &floor);
  EXPECT_DOUBLE_EQ(floor, 13.0 * std::ldexp(1.0, -53));
  EXPECT_EQ(rf(0, 0), 100.0 - 3.0 + 4.0 - 12.0);
}

}  // namespace
}  // namespace vdfx::effects
