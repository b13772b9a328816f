/// @file
/// @brief Spatial-keyframe RBF interpolation of one effect's parameters (contract: "Coordinates
/// and time"; numerics.md: "Spatial keyframe interpolation"; docs/interpolation.md).
///
/// f(n, frame) = sum_k w_k phi(d(x, x_k)) + P(x), phi(d) = d^alpha (d^2 log d at alpha = 2),
/// P linear in the unit direction (x, y, z) and the frame, restricted to the terms the keyframes
/// determine: one global solve. Or local interpolation in time (effects/rbf_windows.h): a window
/// of such solves, each over the keyframes near it in time, blended by weights that sum to one.
/// Immutable once built: share it between threads as shared_ptr<const ...>.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "effects/coords.h"
#include "effects/keyframe.h"
#include "effects/rbf_kernel.h"
#include "effects/rbf_points.h"
#include "effects/rbf_solve.h"
#include "effects/rbf_windows.h"

namespace vdfx::effects {

class RbfInterpolator {
 public:
  /// Solves for `keyframes` (each with `dimension` parameters): globally, or locally in time
  /// when plan_windows says so. `neutral` (size `dimension`, or empty for zeros) is what
  /// evaluate returns when there are no keyframes. Throws std::invalid_argument on settings out
  /// of range, fps <= 0, a wrong parameter count or a window too full to solve (window_problem).
  RbfInterpolator(std::span<const Keyframe> keyframes, int dimension,
                  const InterpolationSettings& settings, double fps,
                  std::vector<double> neutral = {});

  /// Assembles an interpolator from an already solved system (KeyframeSet's incremental path).
  RbfInterpolator(RbfPoints points, const RbfKernel& kernel, PolynomialBasis basis,
                  const RbfSolution& solution, Eigen::VectorXd neutral);

  /// How many of a window's keyframes and centres lie in its own frames (its core, where each
  /// keyframe lies in exactly one window's): the whole's diagnostics count these.
  struct WindowCore {
    int keyframes = 0, centres = 0;
  };
  /// Those of window `j` of `layout`, solved as `window`.
  static WindowCore core_counts(const RbfInterpolator& window, const WindowLayout& layout, int j);

  /// Local interpolation from solved windows (KeyframeSet's windowed path): windows[j] is window
  /// j of `layout`, made by solve_window (windows with the same data may share one), cores[j]
  /// its core_counts. `kernel` is the effect's (its `outside` applies to the keyframes' frame
  /// span [first_frame, last_frame]). O(windows): nothing is solved or counted again.
  RbfInterpolator(const WindowLayout& layout,
                  std::vector<std::shared_ptr<const RbfInterpolator>> windows,
                  std::span<const WindowCore> cores, const RbfKernel& kernel,
                  Eigen::VectorXd neutral, std::int64_t first_frame, std::int64_t last_frame);

  /// One window's solve: the keyframes keyframes[order[i]], i in [data.begin, data.end) (order
  /// sorts them by frame), solved globally and evaluated without a hold (the blended whole
  /// holds). Throws like the first constructor.
  static std::shared_ptr<const RbfInterpolator> solve_window(std::span<const Keyframe> keyframes,
                                                             std::span<const std::size_t> order,
                                                             const WindowData& data, int dimension,
                                                             const InterpolationSettings& settings,
                                                             double fps,
                                                             const Eigen::VectorXd& neutral);

  /// True without keyframes: evaluate returns neutral().
  bool empty() const { return points_.size() == 0 && windows_.empty(); }
  int dimension() const { return static_cast<int>(neutral_.size()); }
  /// Distinct keyframe places (after merging coincident ones).
  int centres() const { return local() ? diagnostics_.centres : points_.size(); }
  /// Interpolated locally in time: windows() and layout() describe how.
  bool local() const { return !windows_.empty(); }
  const WindowLayout& layout() const { return layout_; }
  const std::vector<std::shared_ptr<const RbfInterpolator>>& windows() const { return windows_; }

  /// Values at a view direction and frame. Outside the keyframes' frame span the frame is held
  /// at the nearest end of it unless the settings say Extrapolate (TimeOutside).
  Eigen::VectorXd evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const;
  Eigen::VectorXd evaluate(const Direction& direction, std::int64_t frame) const;
  /// Allocation-free form; `out` must have dimension() entries. `unit` must be a unit vector.
  void evaluate_into(const Eigen::Vector3d& unit, std::int64_t frame, double* out) const;

  /// Of the global solve; when local, over every window (the largest residual and condition,
  /// the least robust method, the most polynomial terms; centres and merges of each window's
  /// own frames).
  const RbfDiagnostics& diagnostics() const { return diagnostics_; }
  const RbfKernel& kernel() const { return kernel_; }
  /// The global solve's polynomial and centres (empty when local: see windows()); in a
  /// turned_for_frame copy the centres are turned, the basis stays the solve's choice.
  const PolynomialBasis& basis() const { return basis_; }
  const RbfPoints& points() const { return points_; }
  const Eigen::VectorXd& neutral() const { return neutral_; }
  /// The frame an evaluation at `frame` uses: clamped into the keyframes' frame span when held.
  std::int64_t effective_frame(std::int64_t frame) const;
  /// This interpolator with its directions turned by the rotation `m`, for evaluations at
  /// `frame` only: its evaluate(u, frame) is this one's evaluate(m u, frame) to rounding, at the
  /// cost of an evaluation without the turn (the distances to the turned centres are those to
  /// the turned direction; the polynomial's direction terms are turned with them). Global: every
  /// centre turned, O(centres); local: the one or two windows `frame` blends, the others shared
  /// untouched (so other frames evaluate wrongly). For StackAtFrame.
  std::shared_ptr<const RbfInterpolator> turned_for_frame(const Eigen::Matrix3d& m,
                                                          std::int64_t frame) const;

 private:
  struct GlobalTag {};
  /// Always the global solve, whatever the settings' reach (solve_window).
  RbfInterpolator(GlobalTag, std::span<const Keyframe> keyframes, int dimension,
                  const RbfKernel& kernel, Eigen::VectorXd neutral);
  void solve_global(std::span<const Keyframe> keyframes, int dimension);
  void find_frame_span();
  void combine_window_diagnostics(std::span<const WindowCore> cores);
  void evaluate_local(const Eigen::Vector3d& unit, std::int64_t frame, double* out) const;
  /// The global solve's centres and polynomial turned (turned_for_frame).
  void turn_globally(const Eigen::Matrix3d& m);
  /// Sets poly_* from the basis and the solve's coefficients (D x r).
  void fold_polynomial(const Eigen::MatrixXd& coefficients_t);

  RbfPoints points_;  // structure of arrays: x, y, z, t contiguous
  RbfKernel kernel_;
  PolynomialBasis basis_;
  Eigen::MatrixXd weights_t_;  // D x m: one column per centre
  // P(n, t) = poly_const_ + poly_lin_ ([n; t] - poly_shift_): the basis's columns with their
  // scales folded in, zero for columns it left out (no switch or division per evaluation, and
  // a turn is a product with poly_lin_'s direction block).
  Eigen::VectorXd poly_const_;
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> poly_lin_;
  Eigen::Vector4d poly_shift_ = Eigen::Vector4d::Zero();
  RbfDiagnostics diagnostics_;
  Eigen::VectorXd neutral_;
  std::int64_t first_frame_ = 0, last_frame_ = 0;                //!< the keyframes' frame span
  WindowLayout layout_;                                          //!< local: the windows' layout
  std::vector<std::shared_ptr<const RbfInterpolator>> windows_;  //!< local: one per window
};

/// The largest dimension local interpolation blends (the blend's scratch lives on the stack).
inline constexpr int kMaxLocalDimension = 16;

}  // namespace vdfx::effects
