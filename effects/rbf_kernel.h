/// @file
/// @brief The radial kernel phi(d) = d^alpha and the space-time distance of the contract.
///
/// Distance between a view (n_v, f_v) and a keyframe (n_k, f_k): d^2 = dsigma^2 + dt^2 with
/// dt = (f_v - f_k) * (24 / fps) * time_scale, the frame difference taken in integers first.
/// dsigma is |n_v - n_k| (Chordal, default) or atan2(|n_v x n_k|, n_v . n_k) (Geodesic).
/// alpha == 2 exactly uses the thin-plate kernel d^2 log d: d^2 itself is a polynomial and the
/// system would be singular (docs/interpolation.md).
#pragma once

#include <Eigen/Core>

#include "effects/keyframe.h"

namespace vdfx::effects {

enum class RbfKernelKind {
  Linear,     //!< alpha == 1: phi = d (a square root, the fast path)
  Power,      //!< phi = d^alpha, alpha != 1, 2
  ThinPlate,  //!< alpha == 2: phi = d^2 log d
};

struct RbfKernel {
  double alpha = 1.0;
  RbfKernelKind kind = RbfKernelKind::Linear;
  AngularDistance distance = AngularDistance::Chordal;
  double time_factor = 24.0 / 30.0;  //!< (24 / fps) * time_scale: time units per frame
  /// Evaluation outside the keyframes' frame span: hold the end values (default) or extrapolate.
  TimeOutside outside = TimeOutside::Hold;

  /// Validates the ranges of keyframe.h and fps > 0; throws std::invalid_argument saying which.
  static RbfKernel from(const InterpolationSettings& settings, double fps);

  /// True when the kernel is conditionally definite of order 2 (needs the linear terms):
  /// alpha > 2 and the thin-plate kernel. Below 2 it is conditionally negative definite of
  /// order 1 (the constant suffices).
  bool order_two() const { return kind == RbfKernelKind::ThinPlate || alpha > 2.0; }

  /// phi as a function of the squared distance.
  double phi_of_d2(double d2) const;
  /// phi applied in place to an array of squared distances (vectorised by Eigen).
  void apply_phi(Eigen::Ref<Eigen::ArrayXd> d2) const;

  /// Squared angular distance between unit vectors.
  double angular_d2(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
};

}  // namespace vdfx::effects
