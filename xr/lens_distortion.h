/// @file
/// @brief The radial lens model as the GPU passes need it (tangent units about the optical centre).
///
/// Convention: a ray the wearer sees at tangent radius r_u (from the eye's optical centre) comes
/// from the panel point at radius r_d = s_c (r_u + c1 r_u^3 + c2 r_u^5), s_c the lateral
/// chromatic scale of channel c (numerics.md "Lens pre-distortion"). Pre-distortion therefore needs
/// the inverse per panel point; the through-the-lens simulation applies the forward model.
/// Beyond the first zero of dr_d/dr_u the model folds: no inverse exists there, so everything
/// beyond r_d_max = f(r_max) is drawn black.
///
/// Temporary: effects/lens_model.h (another branch) owns the lens model; this header keeps only
/// what the GPU passes consume so the switch after that merge is one include.
#pragma once

#include <Eigen/Core>
#include <limits>

namespace vdfx::xr {

struct LensDistortion {
  double c1 = 0.0, c2 = 0.0;
  Eigen::Vector3d lca_scale{1.0, 1.0, 1.0};  //!< per channel (R, G, B) radial scale s_c

  /// r_u + c1 r_u^3 + c2 r_u^5 (no LCA).
  double forward(double r_u) const { const double r2 = r_u * r_u; return r_u * (1 + r2 * (c1 + c2 * r2)); }
  /// The largest r_u where the forward map still increases (infinity when it never stops).
  double max_valid_undistorted_radius() const;
  /// forward(max_valid_undistorted_radius()), infinity when unbounded.
  double max_valid_distorted_radius() const;
  /// Newton inverse of forward() with an iteration cap; NaN beyond the valid radius.
  double inverse(double r_d, int max_iterations = 8) const;
  bool is_identity() const { return c1 == 0.0 && c2 == 0.0 && lca_scale == Eigen::Vector3d::Ones(); }
};

}  // namespace vdfx::xr
