/// @file
/// @brief Dense solve of the RBF saddle-point system by the null-space method.
///
/// [A P; P^T 0] [w; c] = [F; 0] with A_ij = phi(|x_i - x_j|), P the active polynomial columns.
/// P = Q [R; 0] (Householder, <= 5 columns); w = Q2 u with (Q2^T A Q2) u = Q2^T F. The projected
/// block is definite for conditionally definite kernels (negative for alpha < 2, positive for
/// alpha > 2 and thin-plate), so a Cholesky factorisation of +-K is tried first; a full-pivot LU
/// follows when it fails (e.g. the paper's geodesic distance), and a least-squares solve when K is
/// singular, so the result is always finite. One step of iterative refinement runs when the
/// residual is above kRefineTolerance.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "effects/rbf_kernel.h"
#include "effects/rbf_points.h"

namespace vdfx::effects {

enum class RbfSolveMethod {
  Empty,       //!< no keyframes
  Polynomial,  //!< one centre: the constant only
  NullSpaceCholesky,
  NullSpaceLu,   //!< Cholesky failed: the projected block is not definite
  LeastSquares,  //!< the projected block is singular: minimum-norm solution
};
std::string_view to_string(RbfSolveMethod m);

struct RbfDiagnostics {
  int keyframes = 0;     //!< as given
  int centres = 0;       //!< after merging
  int merged = 0;        //!< keyframes - centres
  int active_terms = 0;  //!< polynomial columns kept (of 1, x, y, z, t)
  RbfSolveMethod method = RbfSolveMethod::Empty;
  double max_residual = 0.0;        //!< max |interpolant - value| over the centres, absolute
  double relative_residual = 0.0;   //!< max_residual / max |value| (0 when all values are 0)
  double condition_estimate = 1.0;  //!< 1-norm condition estimate of the projected block
  bool refined = false;             //!< an iterative refinement step ran
};

/// Residual above which one refinement step runs (relative to the largest value).
inline constexpr double kRefineTolerance = 1e-13;

struct RbfSolution {
  Eigen::MatrixXd weights;       //!< m x D radial weights
  Eigen::MatrixXd coefficients;  //!< r x D polynomial coefficients (basis columns order)
  RbfDiagnostics diagnostics;
};

/// The kernel matrix A (m x m, symmetric).
Eigen::MatrixXd kernel_matrix(const RbfPoints& points, const RbfKernel& kernel);
/// The same written to `a`, m x m already (the solve's own storage).
void kernel_matrix_into(const RbfPoints& points, const RbfKernel& kernel,
                        Eigen::Ref<Eigen::MatrixXd> a);
/// One row of A: phi between (n, t) and every centre, written to out (size m).
void kernel_row(const RbfPoints& points, const RbfKernel& kernel, const Eigen::Vector3d& n,
                double t, Eigen::Ref<Eigen::ArrayXd> out);
/// The polynomial matrix P (m x r).
Eigen::MatrixXd polynomial_matrix(const RbfPoints& points, const PolynomialBasis& basis);
/// Q2^T A Q2: the kernel matrix projected onto the null space of P^T (what must be definite).
Eigen::MatrixXd projected_kernel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p);

/// Solves for weights and coefficients; never returns non-finite numbers for finite input.
/// With `inverse` set, also writes the explicit inverse of the saddle-point matrix, ordered
/// [polynomial rows (r); centres (m)] (used by KeyframeSet's bordered updates; O(m^3) more).
/// With `kernel_out` set, also hands over the kernel matrix A the solve assembled (m x m).
RbfSolution solve_rbf(const RbfPoints& points, const RbfKernel& kernel,
                      const PolynomialBasis& basis, Eigen::MatrixXd* inverse = nullptr,
                      Eigen::MatrixXd* kernel_out = nullptr);

/// Max |A w + P c - F| over the rows listed in `rows` (all when empty), computing rows of A on
/// the fly, and max |P^T w|: the larger of the two.
double rbf_residual(const RbfPoints& points, const RbfKernel& kernel, const PolynomialBasis& basis,
                    const Eigen::MatrixXd& weights, const Eigen::MatrixXd& coefficients,
                    const std::vector<int>& rows = {});

}  // namespace vdfx::effects
