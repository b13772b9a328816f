/// @file
/// @brief Radial distortion, its inverses and LCA (see lens_model.h and docs/lens.md).
#include "effects/lens_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vdfx::effects {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Smallest r > 0 with 1 + 3 c1 r^2 + 5 c2 r^4 = 0, or +inf. Solved as a quadratic in x = r^2
/// with the cancellation-free form of the roots (q = -(b + sign(b) sqrt(disc)) / 2).
double first_derivative_root(double c1, double c2) {
  const double a = 5.0 * c2, b = 3.0 * c1;
  double x = kInf;
  if (a == 0.0) {
    if (b < 0.0) x = -1.0 / b;
  } else {
    const double disc = b * b - 4.0 * a;
    if (disc >= 0.0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      for (const double root : {q / a, 1.0 / q}) {
        if (root > 0.0) x = std::min(x, root);
      }
    }
  }
  return std::sqrt(x);
}

}  // namespace

LensModel::LensModel(const LensParams& params) : params_(params) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("LensModel: " + what);
  };
  if (!std::isfinite(params.c1) || !std::isfinite(params.c2)) fail("c1, c2 must be finite");
  if (!(params.radius > 0.0) || !std::isfinite(params.radius)) fail("radius must be > 0");
  for (const double s : params.lca_scale) {
    if (!(s > 0.0) || !std::isfinite(s)) fail("lca_scale entries must be > 0");
  }
  r_u_max_ = first_derivative_root(params.c1, params.c2);
  r_d_max_ = std::isfinite(r_u_max_) ? forward(r_u_max_) : kInf;
}

double LensModel::forward(double r_u) const {
  const double r2 = r_u * r_u;
  return r_u * (1.0 + r2 * (params_.c1 + r2 * params_.c2));
}

double LensModel::derivative(double r_u) const {
  const double r2 = r_u * r_u;
  return 1.0 + r2 * (3.0 * params_.c1 + r2 * 5.0 * params_.c2);
}

std::optional<double> LensModel::inverse_closed_form(double r_d) const {
  if (!(r_d >= 0.0) || !(r_d < r_d_max_)) return std::nullopt;
  const double c1 = params_.c1, c2 = params_.c2;
  const double r2 = r_d * r_d, r4 = r2 * r2, r6 = r4 * r2, r8 = r4 * r4;
  // Mallon and Whelan, "Precise radial un-distortion of images", ICPR 2004, eq. (numerics.md).
  const double num = c1 * r2 + c2 * r4 + c1 * c1 * r4 + c2 * c2 * r8 + 2.0 * c1 * c2 * r6;
  const double den = 1.0 + 4.0 * c1 * r2 + 6.0 * c2 * r4;
  return r_d - r_d * num / den;
}

InverseResult LensModel::inverse_newton(double r_d) const {
  InverseResult result;
  if (!(r_d >= 0.0) || !(r_d < r_d_max_)) return result;
  result.valid = true;
  if (r_d == 0.0) return result;
  // Bracket [lo, hi] with f(lo) <= r_d <= f(hi) on the monotonic branch.
  double lo = 0.0, hi = r_u_max_;
  if (!std::isfinite(hi)) {
    hi = std::max(r_d, 1.0);
    for (int i = 0; i < 64 && forward(hi) < r_d; ++i) hi *= 2.0;
  }
  double r = inverse_closed_form(r_d).value_or(r_d);
  if (!(r > lo && r < hi)) r = 0.5 * (lo + hi);
  for (int it = 0; it < kMaxIterations; ++it) {
    result.iterations = it + 1;
    const double residual = forward(r) - r_d;
    if (residual == 0.0) break;
    (residual < 0.0 ? lo : hi) = r;
    double next = r - residual / derivative(r);
    // A step below the rounding of r is convergence. Tested before the bracket: at the root, r
    // may itself have just become lo or hi (the residual is rounding noise of either sign), and
    // a Newton step that stays on r must not be mistaken for an overshoot and bisected away.
    if (std::abs(next - r) <= 2.0 * std::numeric_limits<double>::epsilon() * r) break;
    // Newton can overshoot where f' is small (near the monotonic limit): bisect instead.
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    r = next;
    if (hi - lo <= std::numeric_limits<double>::epsilon() * hi) break;
  }
  result.r_u = r;
  return result;
}

std::optional<double> LensModel::inverse(double r_d, InverseMethod method) const {
  if (method == InverseMethod::ClosedForm) return inverse_closed_form(r_d);
  const InverseResult res = inverse_newton(r_d);
  if (!res.valid) return std::nullopt;
  return res.r_u;
}

std::optional<Eigen::Vector2d> LensModel::view_to_panel(const Eigen::Vector2d& t_u,
                                                        int channel) const {
  const double R = params_.radius;
  const double r_u = t_u.norm() / R;
  if (!(r_u < r_u_max_)) return std::nullopt;
  if (r_u == 0.0) return Eigen::Vector2d::Zero();
  return t_u * (params_.lca_scale.at(channel) * forward(r_u) / r_u);
}

std::optional<Eigen::Vector2d> LensModel::scaled_inverse(const Eigen::Vector2d& t_d, double scale,
                                                         InverseMethod method) const {
  const double r_d = t_d.norm() / (params_.radius * scale);
  const std::optional<double> r_u = inverse(r_d, method);
  if (!r_u) return std::nullopt;
  if (r_d == 0.0) return Eigen::Vector2d::Zero();
  return t_d * (*r_u / (r_d * scale));
}

std::optional<Eigen::Vector2d> LensModel::panel_to_view(const Eigen::Vector2d& t_d, int channel,
                                                        InverseMethod method) const {
  return scaled_inverse(t_d, params_.lca_scale.at(channel), method);
}

std::optional<Eigen::Vector2d> LensModel::source_for_panel(const Eigen::Vector2d& t_d, int channel,
                                                           bool lca_correction,
                                                           InverseMethod method) const {
  return scaled_inverse(t_d, lca_correction ? params_.lca_scale.at(channel) : 1.0, method);
}

Eigen::Vector2d EyeLens::pixel_to_tan(const Eigen::Vector2d& px) const {
  return fov.tangent_at(px, width, height);
}

Eigen::Vector2d EyeLens::tan_to_pixel(const Eigen::Vector2d& t) const {
  return fov.pixel_at(t, width, height);
}

Eigen::Vector2d EyeLens::tan_to_uv(const Eigen::Vector2d& t) const {
  return fov.uv_of(t);
}

ChannelSamples panel_source_uv(const EyeLens& eye, const Eigen::Vector2d& px, bool lca_correction,
                               InverseMethod method) {
  ChannelSamples out;
  const Eigen::Vector2d t_d = eye.pixel_to_tan(px);
  for (int c = 0; c < 3; ++c) {
    const auto t_u = eye.lens.source_for_panel(t_d, c, lca_correction, method);
    out.valid[c] = t_u.has_value();
    out.uv[c] = t_u ? eye.tan_to_uv(*t_u) : Eigen::Vector2d::Constant(-1.0);
  }
  return out;
}

std::optional<Eigen::Vector2d> through_lens_panel_px(const EyeLens& eye,
                                                     const Eigen::Vector2d& view_px, int channel) {
  const auto t_d = eye.lens.view_to_panel(eye.pixel_to_tan(view_px), channel);
  if (!t_d) return std::nullopt;
  return eye.tan_to_pixel(*t_d);
}

}  // namespace vdfx::effects
