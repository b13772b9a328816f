/// @file
/// @brief Dot2 residual of the saddle-point system (see rbf_exact_residual.h).
///
/// Compiled with -ffp-contract=off (effects/CMakeLists.txt): the error-free transformations
/// below are exact only if the compiler keeps every product and sum separately rounded.
#include "effects/rbf_exact_residual.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "effects/solve_threads.h"

namespace vdfx::effects {
namespace {

/// Accumulates s + c += x * y for whole columns: (s, c) is a running (sum, error) pair per row;
/// with `sq`, also sq += (x * y)^2.
template <bool kSquares>
void axpy_dot2(const double* x, double y, double* s, double* c, double* sq, Eigen::Index n) {
  for (Eigen::Index i = 0; i < n; ++i) {
    const double p = x[i] * y;
    if constexpr (kSquares) sq[i] += p * p;
    const double e = std::fma(x[i], y, -p);  // p + e == x y exactly
    const double t = s[i] + p;
    const double z = t - s[i];
    const double q = (s[i] - (t - z)) + (p - z);  // t + q == s + p exactly
    s[i] = t;
    c[i] += q + e;
  }
}

}  // namespace

double saddle_residual_dot2(Eigen::Ref<const Eigen::MatrixXd> a, const Eigen::MatrixXd& p,
                            const Eigen::MatrixXd& f, const Eigen::MatrixXd& g,
                            const Eigen::MatrixXd& w, const Eigen::MatrixXd& c, Eigen::MatrixXd& rf,
                            Eigen::MatrixXd& rg, double* rounding_floor) {
  const Eigen::Index m = a.rows(), r = p.cols(), d = f.cols();
  rf.resize(m, d);
  rg.resize(r, d);
  std::vector<double> sum(static_cast<std::size_t>(m)), err(static_cast<std::size_t>(m)),
      sq(static_cast<std::size_t>(m));
  double floor = 0.0;
  for (Eigen::Index k = 0; k < d; ++k) {
    std::copy_n(f.col(k).data(), m, sum.begin());
    std::fill(err.begin(), err.end(), 0.0);
    std::fill(sq.begin(), sq.end(), 0.0);
    // Column by column through A and P: contiguous, vectorisable sweeps. Rows are independent
    // (each row's sum runs in the same order): split between the solve's threads.
    parallel_parts(
        m, kParallelSolveMin, [m](int part, int parts) { return m * part / parts; },
        [&](std::ptrdiff_t lo, std::ptrdiff_t hi) {
          const Eigen::Index len = hi - lo;
          double *s = sum.data() + lo, *e = err.data() + lo, *q2 = sq.data() + lo;
          for (Eigen::Index j = 0; j < m; ++j)
            axpy_dot2<true>(a.col(j).data() + lo, -w(j, k), s, e, q2, len);
          for (Eigen::Index q = 0; q < r; ++q)
            axpy_dot2<true>(p.col(q).data() + lo, -c(q, k), s, e, q2, len);
        });
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto u = static_cast<std::size_t>(i);
      rf(i, k) = sum[u] + err[u];
      floor = std::max(floor, sq[u]);
    }
    for (Eigen::Index q = 0; q < r; ++q) {
      // g - P^T w: each row of P^T against w, as one (sum, error) pair.
      double s = g(q, k), e = 0.0;
      for (Eigen::Index i = 0; i < m; ++i) axpy_dot2<false>(&p(i, q), -w(i, k), &s, &e, nullptr, 1);
      rg(q, k) = s + e;
    }
  }
  // Unit roundoff times the largest row's 2-norm of its terms (see the header).
  if (rounding_floor)
    *rounding_floor = 0.5 * std::numeric_limits<double>::epsilon() * std::sqrt(floor);
  const double worst_f = rf.size() ? rf.cwiseAbs().maxCoeff() : 0.0;
  const double worst_g = rg.size() ? rg.cwiseAbs().maxCoeff() : 0.0;
  return std::max(worst_f, worst_g);
}

}  // namespace vdfx::effects
