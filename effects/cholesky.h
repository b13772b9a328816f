/// @file
/// @brief Cholesky factorisation in place, on the solve's threads (effects/solve_threads.h).
///
/// The dense solve's largest step (a 1000 x 1000 factor is three quarters of its arithmetic).
/// Right-looking and blocked (Golub and Van Loan, "Matrix Computations", 4th ed., section 4.2.9):
/// for each block column of kCholeskyBlock columns, the diagonal block is factorised (Eigen's
/// own blocked LLT), the panel below it is solved against that factor, and the trailing lower
/// triangle is updated with the panel (a symmetric rank-k update and a matrix product). The
/// panel's rows and the trailing columns are cut into kCholeskyParts fixed parts of equal work,
/// each taken by whichever of the solve's threads comes first (a thread the system does not run
/// meanwhile holds nothing up): a part is the same Eigen call whichever thread runs it, so the
/// factor has the same bits on one thread as on two. Below kParallelSolveMin columns it is
/// Eigen's LLT itself.
#pragma once

#include <Eigen/Core>

namespace vdfx::effects {

/// Columns per block column (a multiple of the GEMM kernels' 4- and 8-row panels).
inline constexpr Eigen::Index kCholeskyBlock = 96;
/// Parts of a panel's rows and of a trailing update, taken by whichever thread comes first.
inline constexpr int kCholeskyParts = 4;

/// Factorises the symmetric positive definite matrix whose lower triangle `a` holds:
/// a = L L^T, L written over that triangle (the strict upper one is neither read nor written).
/// False where a pivot is not positive (the matrix is not positive definite, as
/// Eigen::LLT's NumericalIssue); the triangle then holds a partial factor.
bool cholesky_in_place(Eigen::Ref<Eigen::MatrixXd> a);

/// ||a||_1 (the largest absolute column sum) of the symmetric matrix whose lower triangle `a`
/// holds, in one pass over that triangle.
double symmetric_norm1_lower(Eigen::Ref<const Eigen::MatrixXd> a);

/// The factor cholesky_in_place wrote, for solves and the condition estimate.
class CholeskyFactor {
 public:
  // What Eigen's condition estimator reads of a decomposition.
  using MatrixType = Eigen::MatrixXd;
  using Scalar = double;
  using RealScalar = double;

  /// `l`: the factor in the lower triangle; `norm1`: ||L L^T||_1 (symmetric_norm1_lower before
  /// the factorisation). The factor is referenced, not copied.
  CholeskyFactor(Eigen::Ref<const Eigen::MatrixXd> l, double norm1) : l_(l), norm1_(norm1) {}

  Eigen::Index rows() const { return l_.rows(); }
  Eigen::Index cols() const { return l_.cols(); }
  /// x with L L^T x = b.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;
  /// L L^T is symmetric: its adjoint is itself (the condition estimator solves with both).
  const CholeskyFactor& adjoint() const { return *this; }
  /// Reciprocal 1-norm condition estimate (Hager and Higham, as Eigen::LLT::rcond()).
  double rcond() const;

 private:
  Eigen::Ref<const Eigen::MatrixXd> l_;
  double norm1_;
};

}  // namespace vdfx::effects
