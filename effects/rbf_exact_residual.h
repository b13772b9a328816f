/// @file
/// @brief The residual of the RBF saddle-point system summed in twice double precision.
///
/// Iterative refinement only helps when the residual is computed more accurately than the
/// solution: near-coincident centres make the weights large, their products cancel, and a residual
/// summed in double would be as wrong as the solution itself. Each entry is summed with the Dot2
/// algorithm of Ogita, Rump and Oishi ("Accurate sum and dot product", SIAM J. Sci. Comput. 26,
/// 2005): error-free products (one FMA each) and error-free sums (Knuth's TwoSum), so the result
/// is as accurate as if computed in quadruple precision and then rounded. It vectorises (4 lanes
/// with AVX2) where long double cannot.
#pragma once

#include <Eigen/Core>

namespace vdfx::effects {

/// rf = f - A w - P c (m x D) and rg = g - P^T w (r x D) for a full symmetric A (m x m) and P
/// (m x r). Returns max(|rf|, |rg|).
double saddle_residual_dot2(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p,
                            const Eigen::MatrixXd& f, const Eigen::MatrixXd& g,
                            const Eigen::MatrixXd& w, const Eigen::MatrixXd& c, Eigen::MatrixXd& rf,
                            Eigen::MatrixXd& rg);

}  // namespace vdfx::effects
