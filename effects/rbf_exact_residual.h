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
/// (m x r). Returns max(|rf|, |rg|). With `rounding_floor`, also writes u max_i ||t_i||_2, u the
/// unit roundoff and t_i row i's terms (A_ij w_j, P_iq c_q): the residual that rounding w and c
/// to double leaves in that row is a sum of such terms each off by up to u of itself, about
/// u ||t_i||_2 / sqrt(3) in size where the roundings are independent. A residual below the
/// floor is about as small as double weights can make it: refinement stops there (at N = 1000 a
/// second step never lowered it).
double saddle_residual_dot2(Eigen::Ref<const Eigen::MatrixXd> a, const Eigen::MatrixXd& p,
                            const Eigen::MatrixXd& f, const Eigen::MatrixXd& g,
                            const Eigen::MatrixXd& w, const Eigen::MatrixXd& c, Eigen::MatrixXd& rf,
                            Eigen::MatrixXd& rg, double* rounding_floor = nullptr);

}  // namespace vdfx::effects
