/// @file
/// @brief RbfInterpolator: solve at construction, fast vectorised evaluation.
#include "effects/rbf_interpolator.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vdfx::effects {

namespace {
Eigen::VectorXd neutral_vector(std::vector<double> neutral, int dimension) {
  if (dimension < 1) throw std::invalid_argument("RbfInterpolator: dimension must be >= 1");
  if (neutral.empty()) return Eigen::VectorXd::Zero(dimension);
  if (static_cast<int>(neutral.size()) != dimension)
    throw std::invalid_argument("RbfInterpolator: neutral has " + std::to_string(neutral.size()) +
                                " values, expected " + std::to_string(dimension));
  return Eigen::Map<const Eigen::VectorXd>(neutral.data(), dimension);
}
}  // namespace

RbfInterpolator::RbfInterpolator(std::span<const Keyframe> keyframes, int dimension,
                                 const InterpolationSettings& settings, double fps,
                                 std::vector<double> neutral)
    : kernel_(RbfKernel::from(settings, fps)),
      neutral_(neutral_vector(std::move(neutral), dimension)) {
  points_ = merge_keyframes(keyframes, dimension);
  basis_ = select_polynomial_basis(points_);
  const RbfSolution s = solve_rbf(points_, kernel_, basis_);
  weights_t_ = s.weights.transpose();
  coeffs_t_ = s.coefficients.transpose();
  diagnostics_ = s.diagnostics;
  find_frame_span();
}

RbfInterpolator::RbfInterpolator(RbfPoints points, const RbfKernel& kernel, PolynomialBasis basis,
                                 const RbfSolution& solution, Eigen::VectorXd neutral)
    : points_(std::move(points)),
      kernel_(kernel),
      basis_(std::move(basis)),
      weights_t_(solution.weights.transpose()),
      coeffs_t_(solution.coefficients.transpose()),
      diagnostics_(solution.diagnostics),
      neutral_(std::move(neutral)) {
  find_frame_span();
}

void RbfInterpolator::find_frame_span() {
  if (points_.frame.empty()) return;
  const auto [lo, hi] = std::minmax_element(points_.frame.begin(), points_.frame.end());
  first_frame_ = *lo;
  last_frame_ = *hi;
}

std::int64_t RbfInterpolator::effective_frame(std::int64_t frame) const {
  if (kernel_.outside == TimeOutside::Extrapolate || points_.size() == 0) return frame;
  return std::clamp(frame, first_frame_, last_frame_);
}

Eigen::VectorXd RbfInterpolator::evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const {
  Eigen::VectorXd out(dimension());
  evaluate_into(unit, frame, out.data());
  return out;
}

Eigen::VectorXd RbfInterpolator::evaluate(const Direction& direction, std::int64_t frame) const {
  return evaluate(to_unit(direction), frame);
}

void RbfInterpolator::evaluate_into(const Eigen::Vector3d& n, std::int64_t frame,
                                    double* out_ptr) const {
  const int d = dimension();
  Eigen::Map<Eigen::VectorXd> out(out_ptr, d);
  const int m = points_.size();
  if (m == 0) {
    out = neutral_;
    return;
  }
  // Integer difference first: exact for any frame numbers below 2^53.
  const double t = static_cast<double>(effective_frame(frame) - points_.frame_origin);
  double prow[5];
  basis_.row(n, t, prow);
  out.noalias() = coeffs_t_ * Eigen::Map<const Eigen::VectorXd>(prow, basis_.size());

  // Blocks of centres small enough to stay in L1 and on the stack (no allocation per call).
  constexpr int kBlock = 256;
  Eigen::Array<double, Eigen::Dynamic, 1, 0, kBlock, 1> d2;
  const double tf = kernel_.time_factor;
  for (int s = 0; s < m; s += kBlock) {
    const int len = std::min(kBlock, m - s);
    d2.resize(len);
    if (kernel_.distance == AngularDistance::Chordal) {
      d2 = (points_.x.segment(s, len) - n.x()).square() +
           (points_.y.segment(s, len) - n.y()).square() +
           (points_.z.segment(s, len) - n.z()).square() +
           ((points_.t.segment(s, len) - t) * tf).square();
    } else {
      for (int i = 0; i < len; ++i) {
        const double dt = (points_.t[s + i] - t) * tf;
        d2[i] = kernel_.angular_d2(points_.unit(s + i), n) + dt * dt;
      }
    }
    switch (kernel_.kind) {
      case RbfKernelKind::Linear: d2 = d2.sqrt(); break;
      case RbfKernelKind::ThinPlate:
        d2 = (d2 > 0.0).select(0.5 * d2 * d2.max(1e-300).log(), 0.0);
        break;
      case RbfKernelKind::Power: d2 = (0.5 * kernel_.alpha * d2.log()).exp(); break;
    }
    if (d == 1) {
      out[0] += weights_t_.row(0).segment(s, len).dot(d2.matrix().transpose());
    } else {
      out.noalias() += weights_t_.middleCols(s, len) * d2.matrix();
    }
  }
}

}  // namespace vdfx::effects
