/// @file
/// @brief The blocked Cholesky factorisation on the solve's threads (see cholesky.h).
#include "effects/cholesky.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "effects/solve_threads.h"

namespace vdfx::effects {

namespace {

using Matrix = Eigen::Ref<Eigen::MatrixXd>;
using Eigen::Index;

/// Right-hand sides up to which CholeskyFactor::solve goes a column at a time.
constexpr Eigen::Index kVectorSolves = 4;

/// Start of part p (of kCholeskyParts) of n items, rounded to whole 8-row kernel panels.
Index even_cut(Index n, int p) {
  if (p >= kCholeskyParts) return n;
  return std::min(n, (n * p / kCholeskyParts + 4) / 8 * 8);
}

/// Start of part p of the columns [c0, n) of a trailing lower triangle: equal shares of its area
/// (columns near c0 are the longest), rounded to whole 8-column panels.
Index triangle_part(Index c0, Index n, int p) {
  if (p >= kCholeskyParts) return n;
  return c0 + std::min(n - c0, (triangle_cut(n - c0, p, kCholeskyParts) + 4) / 8 * 8);
}

/// One block column's steps, as parts: the panel's rows against the diagonal block's factor,
/// then the trailing triangle's columns.
class BlockStep {
 public:
  BlockStep(Matrix a, Index k) : a_(a), k_(k), w_(std::min(kCholeskyBlock, a.rows() - k)) {}

  /// The diagonal block's factor; false where it is not positive definite.
  bool factor_diagonal() {
    auto d = a_.block(k_, k_, w_, w_);
    return Eigen::internal::llt_inplace<double, Eigen::Lower>::blocked(d) == -1;
  }

  /// Rows [even_cut(p), even_cut(p + 1)) of the panel below the diagonal block: A21 L11^-T.
  void solve_panel(int p) {
    const Index rs = a_.rows() - k_ - w_, r0 = even_cut(rs, p), r1 = even_cut(rs, p + 1);
    if (r1 <= r0) return;
    auto panel = a_.block(k_ + w_ + r0, k_, r1 - r0, w_);
    a_.block(k_, k_, w_, w_)
        .adjoint()
        .triangularView<Eigen::Upper>()
        .solveInPlace<Eigen::OnTheRight>(panel);
  }

  /// Columns [lo, hi) of the trailing triangle minus the panel's product with itself: the
  /// diagonal square by a symmetric rank-w update, the rows below it by a product.
  void update_trailing(int p) {
    const Index n = a_.rows(), c0 = k_ + w_;
    const Index lo = triangle_part(c0, n, p), hi = triangle_part(c0, n, p + 1);
    if (hi <= lo) return;
    const auto l1 = a_.block(lo, k_, hi - lo, w_);
    a_.block(lo, lo, hi - lo, hi - lo).selfadjointView<Eigen::Lower>().rankUpdate(l1, -1.0);
    if (n > hi)
      a_.block(hi, lo, n - hi, hi - lo).noalias() -= a_.block(hi, k_, n - hi, w_) * l1.transpose();
  }

 private:
  Matrix a_;
  Index k_, w_;
};

}  // namespace

bool cholesky_in_place(Eigen::Ref<Eigen::MatrixXd> a) {
  const Index n = a.rows();
  if (n < kParallelSolveMin)
    return Eigen::internal::llt_inplace<double, Eigen::Lower>::blocked(a) == -1;
  for (Index k = 0; k < n; k += kCholeskyBlock) {
    BlockStep step(a, k);
    if (!step.factor_diagonal()) return false;
    // The parts are taken by whichever of the solve's threads comes first.
    for_each_part(kCholeskyParts, [&step](int p) { step.solve_panel(p); });
    for_each_part(kCholeskyParts, [&step](int p) { step.update_trailing(p); });
  }
  return true;
}

double symmetric_norm1_lower(Eigen::Ref<const Eigen::MatrixXd> a) {
  const Index n = a.rows();
  Eigen::VectorXd sums = Eigen::VectorXd::Zero(n);
  for (Index j = 0; j < n; ++j) {
    // Column j below the diagonal is row j right of it: it adds to column j and to each row's.
    const auto below = a.col(j).tail(n - j - 1).cwiseAbs();
    sums[j] += std::abs(a(j, j)) + below.sum();
    sums.tail(n - j - 1) += below;
  }
  return n > 0 ? sums.maxCoeff() : 0.0;
}

Eigen::MatrixXd CholeskyFactor::solve(const Eigen::MatrixXd& b) const {
  Eigen::MatrixXd x = b;
  const auto lower = l_.triangularView<Eigen::Lower>();
  const auto upper = l_.transpose().triangularView<Eigen::Upper>();
  if (x.cols() > kVectorSolves) {
    lower.solveInPlace(x);
    upper.solveInPlace(x);
    return x;
  }
  // A column at a time: Eigen's solve for a vector (a blocked sweep of matrix-vector products)
  // is several times faster than its solve for a matrix of one column, which packs the factor.
  for (Eigen::Index c = 0; c < x.cols(); ++c) {
    auto col = x.col(c);
    lower.solveInPlace(col);
    upper.solveInPlace(col);
  }
  return x;
}

double CholeskyFactor::rcond() const {
  return Eigen::internal::rcond_estimate_helper(norm1_, *this);
}

}  // namespace vdfx::effects
