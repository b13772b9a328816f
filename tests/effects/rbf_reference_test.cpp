/// @file
/// @brief Cross-check against an independent reference: the full (unreduced) saddle-point
/// system assembled here in long double and solved by a full-pivot LU, evaluated at random views.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <limits>

#include "effects/rbf_interpolator.h"
#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

using LD = long double;
using MatL = Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>;
using VecL = Eigen::Matrix<LD, 3, 1>;

VecL unit_l(const Direction& d) {
  const LD az = static_cast<LD>(d.azimuth_deg) * static_cast<LD>(kPi) / 180;
  const LD alt = static_cast<LD>(d.altitude_deg) * static_cast<LD>(kPi) / 180;
  return {std::cos(alt) * std::sin(az), std::sin(alt), -std::cos(alt) * std::cos(az)};
}

LD phi_l(LD d, double alpha) {
  if (d <= 0) return 0;
  if (alpha == 2.0) return d * d * std::log(d);
  return std::pow(d, static_cast<LD>(alpha));
}

/// The reference interpolant: its own distances and polynomial (the same active columns, as
/// unscaled monomials: the function space does not depend on the scaling).
struct Reference {
  std::vector<VecL> n;
  std::vector<LD> t;
  MatL coef;
  std::vector<int> cols;
  double alpha, tf;

  Eigen::Matrix<LD, Eigen::Dynamic, 1> poly(const VecL& u, LD tt) const {
    Eigen::Matrix<LD, Eigen::Dynamic, 1> p(static_cast<Eigen::Index>(cols.size()));
    for (size_t j = 0; j < cols.size(); ++j)
      p[static_cast<Eigen::Index>(j)] = cols[j] == 0 ? 1 : (cols[j] == 4 ? tt : u[cols[j] - 1]);
    return p;
  }
  /// The basis at (u, tt): the kernel against every centre, then the polynomial columns.
  Eigen::Matrix<LD, Eigen::Dynamic, 1> basis_row(const VecL& u, LD tt) const {
    const Eigen::Index m = static_cast<Eigen::Index>(n.size()),
                       r = static_cast<Eigen::Index>(cols.size());
    Eigen::Matrix<LD, Eigen::Dynamic, 1> row(m + r);
    for (Eigen::Index i = 0; i < m; ++i) {
      const LD dt = (tt - t[static_cast<size_t>(i)]) * tf;
      row[i] = phi_l(std::sqrt((u - n[static_cast<size_t>(i)]).squaredNorm() + dt * dt), alpha);
    }
    row.tail(r) = poly(u, tt);
    return row;
  }
  Eigen::Matrix<LD, Eigen::Dynamic, 1> eval(const VecL& u, LD tt) const {
    return coef.transpose() * basis_row(u, tt);
  }
  /// sum_i |coef_i row_i| per output: the size of the terms that cancel in eval().
  Eigen::Matrix<LD, Eigen::Dynamic, 1> magnitude(const VecL& u, LD tt) const {
    return coef.cwiseAbs().transpose() * basis_row(u, tt).cwiseAbs();
  }
};

Reference solve_reference(const std::vector<Keyframe>& k, int dim, double alpha, double fps,
                          const std::vector<int>& cols) {
  Reference ref{{}, {}, {}, cols, alpha, 24.0 / fps};
  const Eigen::Index m = static_cast<Eigen::Index>(k.size()),
                     r = static_cast<Eigen::Index>(cols.size());
  for (const auto& kf : k) {
    ref.n.push_back(unit_l(kf.direction));
    ref.t.push_back(static_cast<LD>(kf.frame));
  }
  MatL sys = MatL::Zero(m + r, m + r), rhs = MatL::Zero(m + r, dim);
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = 0; j < m; ++j) {
      const LD dt = (ref.t[static_cast<size_t>(i)] - ref.t[static_cast<size_t>(j)]) * ref.tf;
      sys(i, j) = phi_l(
          std::sqrt((ref.n[static_cast<size_t>(i)] - ref.n[static_cast<size_t>(j)]).squaredNorm() +
                    dt * dt),
          alpha);
    }
    const auto p = ref.poly(ref.n[static_cast<size_t>(i)], ref.t[static_cast<size_t>(i)]);
    sys.block(i, m, 1, r) = p.transpose();
    sys.block(m, i, r, 1) = p;
    for (int c = 0; c < dim; ++c)
      rhs(i, c) = k[static_cast<size_t>(i)].params[static_cast<size_t>(c)];
  }
  ref.coef = Eigen::FullPivLU<MatL>(sys).solve(rhs);
  return ref;
}

TEST(RbfReference, MatchesAnIndependentLongDoubleSolveAtRandomViews) {
  const struct {
    int n;
    double alpha;
    std::int64_t frames;
  } cases[] = {{8, 1.0, 100},  {40, 1.0, 300}, {40, 0.5, 300}, {40, 1.5, 0},
               {30, 3.0, 200}, {30, 2.0, 200}, {25, 1.99, 50}};
  std::uint64_t seed = 100;
  for (const auto& c : cases) {
    std::mt19937_64 rng(++seed);
    std::vector<Keyframe> k;
    for (int i = 0; i < c.n; ++i) k.push_back(test::random_keyframe(rng, 2, 0, c.frames));
    InterpolationSettings s;
    s.exponent = c.alpha;
    // The reference is the contract's formula itself, probed up to 20 frames past the span: the
    // hold at the span's ends (rbf_time_test.cpp) is left out here.
    s.outside = TimeOutside::Extrapolate;
    const RbfInterpolator rbf(k, 2, s, 30.0);
    ASSERT_EQ(rbf.diagnostics().merged, 0);
    const Reference ref = solve_reference(k, 2, c.alpha, 30.0, rbf.basis().columns);
    std::uniform_int_distribution<std::int64_t> f(0, c.frames + 20);
    for (int i = 0; i < 100; ++i) {
      const Direction d = test::random_direction(rng);
      const std::int64_t fr = f(rng);
      const Eigen::VectorXd got = rbf.evaluate(d, fr);
      const auto want = ref.eval(unit_l(d), static_cast<LD>(fr));
      const auto mag = ref.magnitude(unit_l(d), static_cast<LD>(fr));
      // 4e-9 for the solve, plus the textbook bound on evaluating a sum of m + r terms in
      // double, gamma_(m+r) * sum |term| (Higham, Accuracy and Stability, ch. 3): large kernel
      // values (alpha 3, long time spans) cancel to O(1) results.
      const double gamma = (c.n + 5) * 0.5 * std::numeric_limits<double>::epsilon();
      for (int j = 0; j < 2; ++j)
        ASSERT_NEAR(got[j], static_cast<double>(want[j]),
                    4e-9 + gamma * static_cast<double>(mag[j]))
            << "n " << c.n << " alpha " << c.alpha << " view " << i;
    }
  }
}

}  // namespace
}  // namespace vdfx::effects
