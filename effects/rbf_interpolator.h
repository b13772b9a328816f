/// @file
/// @brief Spatial-keyframe RBF interpolation of one effect's parameters (contract: "Coordinates
/// and time"; numerics.md: "Spatial keyframe interpolation"; docs/interpolation.md).
///
/// f(n, frame) = sum_k w_k phi(d(x, x_k)) + P(x), phi(d) = d^alpha (d^2 log d at alpha = 2),
/// P linear in the unit direction (x, y, z) and the frame, restricted to the terms the keyframes
/// determine. Immutable once built: share it between threads as shared_ptr<const ...>.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "effects/coords.h"
#include "effects/keyframe.h"
#include "effects/rbf_kernel.h"
#include "effects/rbf_points.h"
#include "effects/rbf_solve.h"

namespace vdfx::effects {

class RbfInterpolator {
 public:
  /// Solves for `keyframes` (each with `dimension` parameters). `neutral` (size `dimension`, or
  /// empty for zeros) is what evaluate returns when there are no keyframes. Throws
  /// std::invalid_argument on settings out of range, fps <= 0 or a wrong parameter count.
  RbfInterpolator(std::span<const Keyframe> keyframes, int dimension,
                  const InterpolationSettings& settings, double fps,
                  std::vector<double> neutral = {});

  /// Assembles an interpolator from an already solved system (KeyframeSet's incremental path).
  RbfInterpolator(RbfPoints points, const RbfKernel& kernel, PolynomialBasis basis,
                  const RbfSolution& solution, Eigen::VectorXd neutral);

  /// True without keyframes: evaluate returns neutral().
  bool empty() const { return points_.size() == 0; }
  int dimension() const { return static_cast<int>(neutral_.size()); }
  int centres() const { return points_.size(); }

  /// Values at a view direction and frame. Outside the keyframes' frame span the frame is held
  /// at the nearest end of it unless the settings say Extrapolate (TimeOutside).
  Eigen::VectorXd evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const;
  Eigen::VectorXd evaluate(const Direction& direction, std::int64_t frame) const;
  /// Allocation-free form; `out` must have dimension() entries. `unit` must be a unit vector.
  void evaluate_into(const Eigen::Vector3d& unit, std::int64_t frame, double* out) const;

  const RbfDiagnostics& diagnostics() const { return diagnostics_; }
  const RbfKernel& kernel() const { return kernel_; }
  const PolynomialBasis& basis() const { return basis_; }
  const RbfPoints& points() const { return points_; }
  const Eigen::VectorXd& neutral() const { return neutral_; }
  /// The frame an evaluation at `frame` uses: clamped into the keyframes' frame span when held.
  std::int64_t effective_frame(std::int64_t frame) const;

 private:
  void find_frame_span();

  RbfPoints points_;  // structure of arrays: x, y, z, t contiguous
  RbfKernel kernel_;
  PolynomialBasis basis_;
  Eigen::MatrixXd weights_t_;  // D x m: one column per centre
  Eigen::MatrixXd coeffs_t_;   // D x r
  RbfDiagnostics diagnostics_;
  Eigen::VectorXd neutral_;
  std::int64_t first_frame_ = 0, last_frame_ = 0;  //!< the centres' frame span
};

}  // namespace vdfx::effects
