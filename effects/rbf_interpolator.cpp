/// @file
/// @brief RbfInterpolator: solve at construction, fast vectorised evaluation.
#include "effects/rbf_interpolator.h"

#include <algorithm>
#include <cmath>
#include <numeric>
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
  if (settings.reach_s || keyframes.size() > kGlobalSolveMaxKeyframes) {
    std::vector<std::size_t> order(keyframes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return keyframes[a].frame < keyframes[b].frame;
    });
    std::vector<std::int64_t> frames(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) frames[i] = keyframes[order[i]].frame;
    if (const auto layout = plan_windows(settings, fps, frames)) {
      if (const auto why = window_problem(settings, fps, frames))
        throw std::invalid_argument("RbfInterpolator: " + *why);
      if (dimension > kMaxLocalDimension)
        throw std::invalid_argument("RbfInterpolator: local interpolation of more than " +
                                    std::to_string(kMaxLocalDimension) + " parameters");
      layout_ = *layout;
      const std::vector<WindowData> data = window_data(layout_, frames);
      std::vector<WindowCore> cores;
      for (std::size_t j = 0; j < data.size(); ++j) {
        // Windows in a gap see the same keyframes: one solve serves them all.
        if (j > 0 && data[j] == data[j - 1])
          windows_.push_back(windows_.back());
        else
          windows_.push_back(
              solve_window(keyframes, order, data[j], dimension, settings, fps, neutral_));
        cores.push_back(core_counts(*windows_.back(), layout_, static_cast<int>(j)));
      }
      first_frame_ = frames.front();
      last_frame_ = frames.back();
      combine_window_diagnostics(cores);
      return;
    }
  }
  solve_global(keyframes, dimension);
}

RbfInterpolator::RbfInterpolator(GlobalTag, std::span<const Keyframe> keyframes, int dimension,
                                 const RbfKernel& kernel, Eigen::VectorXd neutral)
    : kernel_(kernel), neutral_(std::move(neutral)) {
  solve_global(keyframes, dimension);
}

void RbfInterpolator::solve_global(std::span<const Keyframe> keyframes, int dimension) {
  points_ = merge_keyframes(keyframes, dimension);
  basis_ = select_polynomial_basis(points_);
  const RbfSolution s = solve_rbf(points_, kernel_, basis_);
  weights_t_ = s.weights.transpose();
  fold_polynomial(s.coefficients.transpose());
  diagnostics_ = s.diagnostics;
  find_frame_span();
}

std::shared_ptr<const RbfInterpolator> RbfInterpolator::solve_window(
    std::span<const Keyframe> keyframes, std::span<const std::size_t> order, const WindowData& data,
    int dimension, const InterpolationSettings& settings, double fps,
    const Eigen::VectorXd& neutral) {
  std::vector<Keyframe> own;
  own.reserve(data.size());
  for (std::size_t i = data.begin; i < data.end; ++i) own.push_back(keyframes[order[i]]);
  InterpolationSettings local = settings;
  local.outside = TimeOutside::Extrapolate;
  local.reach_s.reset();
  return std::shared_ptr<const RbfInterpolator>(
      new RbfInterpolator(GlobalTag{}, own, dimension, RbfKernel::from(local, fps), neutral));
}

RbfInterpolator::RbfInterpolator(const WindowLayout& layout,
                                 std::vector<std::shared_ptr<const RbfInterpolator>> windows,
                                 std::span<const WindowCore> cores, const RbfKernel& kernel,
                                 Eigen::VectorXd neutral, std::int64_t first_frame,
                                 std::int64_t last_frame)
    : kernel_(kernel),
      neutral_(std::move(neutral)),
      first_frame_(first_frame),
      last_frame_(last_frame),
      layout_(layout),
      windows_(std::move(windows)) {
  if (static_cast<int>(windows_.size()) != layout_.count ||
      static_cast<int>(cores.size()) != layout_.count)
    throw std::invalid_argument("RbfInterpolator: " + std::to_string(windows_.size()) +
                                " windows and " + std::to_string(cores.size()) +
                                " core counts for a layout of " + std::to_string(layout_.count));
  combine_window_diagnostics(cores);
}

RbfInterpolator::WindowCore RbfInterpolator::core_counts(const RbfInterpolator& window,
                                                         const WindowLayout& layout, int j) {
  WindowCore core;
  const RbfPoints& p = window.points_;
  for (int c = 0; c < p.size(); ++c) {
    const double f = static_cast<double>(p.frame[static_cast<std::size_t>(c)]);
    // As blend_at counts a frame's window.
    if (std::floor(f / layout.width) - static_cast<double>(layout.first) != j) continue;
    core.keyframes += p.counts[static_cast<std::size_t>(c)];
    ++core.centres;
  }
  return core;
}

void RbfInterpolator::combine_window_diagnostics(std::span<const WindowCore> cores) {
  RbfDiagnostics d;
  d.method = RbfSolveMethod::Polynomial;
  d.condition_estimate = 0.0;
  for (int j = 0; j < layout_.count; ++j) {
    const RbfDiagnostics& wd = windows_[static_cast<std::size_t>(j)]->diagnostics_;
    d.keyframes += cores[static_cast<std::size_t>(j)].keyframes;
    d.centres += cores[static_cast<std::size_t>(j)].centres;
    d.active_terms = std::max(d.active_terms, wd.active_terms);
    d.method = std::max(d.method, wd.method);
    d.max_residual = std::max(d.max_residual, wd.max_residual);
    d.relative_residual = std::max(d.relative_residual, wd.relative_residual);
    d.condition_estimate = std::max(d.condition_estimate, wd.condition_estimate);
    d.refined = d.refined || wd.refined;
  }
  d.merged = d.keyframes - d.centres;
  diagnostics_ = d;
}

RbfInterpolator::RbfInterpolator(RbfPoints points, const RbfKernel& kernel, PolynomialBasis basis,
                                 const RbfSolution& solution, Eigen::VectorXd neutral)
    : points_(std::move(points)),
      kernel_(kernel),
      basis_(std::move(basis)),
      weights_t_(solution.weights.transpose()),
      diagnostics_(solution.diagnostics),
      neutral_(std::move(neutral)) {
  fold_polynomial(solution.coefficients.transpose());
  find_frame_span();
}

void RbfInterpolator::fold_polynomial(const Eigen::MatrixXd& coefficients_t) {
  const int d = static_cast<int>(coefficients_t.rows());
  poly_const_ = Eigen::VectorXd::Zero(d);
  poly_lin_ = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>::Zero(d, 4);
  poly_shift_ << basis_.dir_shift, basis_.t_shift;
  for (int j = 0; j < basis_.size(); ++j) {
    const int c = basis_.columns[static_cast<std::size_t>(j)];
    if (c == PolynomialBasis::One)
      poly_const_ = coefficients_t.col(j);
    else if (c == PolynomialBasis::T)
      poly_lin_.col(3) = coefficients_t.col(j) / basis_.t_scale;
    else
      poly_lin_.col(c - PolynomialBasis::X) = coefficients_t.col(j) / basis_.dir_scale;
  }
}

void RbfInterpolator::find_frame_span() {
  if (points_.frame.empty()) return;
  const auto [lo, hi] = std::minmax_element(points_.frame.begin(), points_.frame.end());
  first_frame_ = *lo;
  last_frame_ = *hi;
}

std::int64_t RbfInterpolator::effective_frame(std::int64_t frame) const {
  if (kernel_.outside == TimeOutside::Extrapolate || empty()) return frame;
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
  if (local()) {
    evaluate_local(n, frame, out_ptr);
    return;
  }
  const int m = points_.size();
  if (m == 0) {
    out = neutral_;
    return;
  }
  // Integer difference first: exact for any frame numbers below 2^53.
  const double t = static_cast<double>(effective_frame(frame) - points_.frame_origin);
  const Eigen::Vector4d v = Eigen::Vector4d(n.x(), n.y(), n.z(), t) - poly_shift_;
  // Small products row by row, as dot products: Eigen's general matrix-vector product costs
  // tens of nanoseconds more, and more or less by where the caller's `out` lies (a stack's
  // anchored effects, 4 keyframes each, ran 19 % slower for it; docs/anchors.md). Past
  // kRowDotsUpTo centres its vectorised sweep over the columns is the faster.
  constexpr int kRowDotsUpTo = 32;
  for (int r = 0; r < d; ++r) out[r] = poly_const_[r] + poly_lin_.row(r).dot(v.transpose());

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
    if (d == 1 || len <= kRowDotsUpTo) {
      for (int r = 0; r < d; ++r)
        out[r] += weights_t_.row(r).segment(s, len).dot(d2.matrix().transpose());
    } else {
      out.noalias() += weights_t_.middleCols(s, len) * d2.matrix();
    }
  }
}

void RbfInterpolator::evaluate_local(const Eigen::Vector3d& n, std::int64_t frame,
                                     double* out) const {
  const std::int64_t f = effective_frame(frame);
  const WindowBlend b = blend_at(layout_, static_cast<double>(f));
  windows_[static_cast<std::size_t>(b.a)]->evaluate_into(n, f, out);
  if (b.b == b.a) return;
  double other[kMaxLocalDimension];
  windows_[static_cast<std::size_t>(b.b)]->evaluate_into(n, f, other);
  for (int i = 0; i < dimension(); ++i) out[i] += b.weight * (other[i] - out[i]);
}

std::shared_ptr<const RbfInterpolator> RbfInterpolator::turned_for_frame(const Eigen::Matrix3d& m,
                                                                         std::int64_t frame) const {
  auto out = std::make_shared<RbfInterpolator>(*this);
  if (!local()) {
    out->turn_globally(m);
    return out;
  }
  // Only the windows this frame blends are ever evaluated at it (evaluate_local).
  const WindowBlend b = blend_at(layout_, static_cast<double>(effective_frame(frame)));
  for (const int j : {b.a, b.b}) {
    auto& w = out->windows_[static_cast<std::size_t>(j)];
    if (w != windows_[static_cast<std::size_t>(j)]) continue;  // b.a == b.b: already turned
    w = w->turned_for_frame(m, frame);
  }
  return out;
}

void RbfInterpolator::turn_globally(const Eigen::Matrix3d& m) {
  // |m u - c| = |u - m^T c| (and so is the angle): the centres turn the other way.
  for (int i = 0; i < points_.size(); ++i) {
    const Eigen::Vector3d c = m.transpose() * points_.unit(i);
    points_.x[i] = c.x(), points_.y[i] = c.y(), points_.z[i] = c.z();
  }
  // P's direction terms g (m u - s) = (g m) (u - m^T s).
  poly_lin_.leftCols<3>() = (poly_lin_.leftCols<3>() * m).eval();
  poly_shift_.head<3>() = m.transpose() * poly_shift_.head<3>();
}

}  // namespace vdfx::effects
