/// @file
/// @brief The pixel footprint's Jacobian and taps (see pixel_footprint.h).
#include "effects/pixel_footprint.h"

#include <algorithm>
#include <cmath>

#include "effects/coords.h"

namespace vdfx::effects {
namespace {

/// d(azimuth, altitude) for a change e of the ray d (radians per unit of e). On the pole axis
/// (h^2 below `min_h2`, which also covers a float's rounding of a ray meant to be on it) every
/// azimuth meets: the azimuth's rate is that of a ray at the floor's distance, moved across.
Eigen::Vector2d angle_differential(const Eigen::Vector3d& d, const Eigen::Vector3d& e,
                                   double min_h2) {
  const double h2 = d.x() * d.x() + d.z() * d.z();
  if (h2 < min_h2) return {std::hypot(e.x(), e.z()) / std::sqrt(min_h2), 0.0};
  const double h = std::sqrt(h2);
  const double daz = (-d.z() * e.x() + d.x() * e.z()) / h2;
  const double dh = (d.x() * e.x() + d.z() * e.z()) / h;
  const double dalt = (h * e.y() - d.y() * dh) / (h2 + d.y() * d.y());
  return {daz, dalt};
}

}  // namespace

Eigen::Matrix2d equirect_jacobian(const Eigen::Vector3d& d, const Eigen::Vector3d& ex,
                                  const Eigen::Vector3d& ey, const TexelScale& texels) {
  // The pole axis: within 1e-6 of a radian (relative to |d|: d is unnormalised), as the shader.
  const double min_h2 = 1e-12 * d.squaredNorm();
  const Eigen::Vector2d ax = angle_differential(d, ex, min_h2);
  const Eigen::Vector2d ay = angle_differential(d, ey, min_h2);
  // u = 0.5 + az / 2 pi, v = 0.5 - alt / pi.
  const double su = texels.per_turn / (2.0 * kPi), sv = -texels.per_half_turn / kPi;
  Eigen::Matrix2d j;
  j << su * ax.x(), su * ay.x(), sv * ax.y(), sv * ay.y();
  return j;
}

double FootprintTaps::weight(int k) const {
  const double lo = std::max(k * spacing - 0.5 * spacing, -0.5);
  const double hi = std::min(k * spacing + 0.5 * spacing, 0.5);
  return std::max(hi - lo, 0.0);
}

FootprintTaps footprint_taps(const Eigen::Matrix2d& j, double max_anisotropy, double turn_texels) {
  // J^T J = [[a, b], [b, c]]: its eigenvalues are the squared singular values of J, its leading
  // eigenvector the screen direction that J stretches most.
  const double a = j.col(0).squaredNorm(), b = j.col(0).dot(j.col(1)), c = j.col(1).squaredNorm();
  const double mean = 0.5 * (a + c);
  const double dev = std::hypot(0.5 * (a - c), b);
  double s1 = std::sqrt(mean + dev);
  // s1 s2 = |det J|: the minor axis without the cancellation of mean - dev.
  const double det = j(0, 0) * j(1, 1) - j(0, 1) * j(1, 0);
  double s2 = s1 > 0.0 ? std::abs(det) / s1 : 0.0;
  s1 = std::min(s1, turn_texels);
  s2 = std::min(s2, s1);
  FootprintTaps t;
  const double theta = (b == 0.0 && a == c) ? 0.0 : 0.5 * std::atan2(2.0 * b, a - c);
  t.axis = {std::cos(theta), std::sin(theta)};
  const double r = std::clamp(s1 / std::max(s2, 1.0), 1.0, std::max(max_anisotropy, 1.0));
  t.spacing = 1.0 / r;
  t.half_count = static_cast<int>(std::ceil(0.5 * (r - 1.0)));
  t.lod = std::log2(std::max({s1 / r, s2, 1.0}));
  return t;
}

}  // namespace vdfx::effects
