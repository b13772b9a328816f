/// @file
/// @brief LensDistortion: valid radius and the capped Newton inverse.
#include "xr/lens_distortion.h"

#include <algorithm>
#include <cmath>

namespace vdfx::xr {

double LensDistortion::max_valid_undistorted_radius() const {
  // f'(r) = 1 + 3 c1 r^2 + 5 c2 r^4: smallest positive root in x = r^2 of 5 c2 x^2 + 3 c1 x + 1.
  constexpr double inf = std::numeric_limits<double>::infinity();
  double x = inf;
  if (c2 == 0.0) {
    if (c1 < 0.0) x = -1.0 / (3.0 * c1);
  } else {
    const double disc = 9.0 * c1 * c1 - 20.0 * c2;
    if (disc >= 0.0) {
      const double s = std::sqrt(disc);
      for (double root : {(-3.0 * c1 - s) / (10.0 * c2), (-3.0 * c1 + s) / (10.0 * c2)})
        if (root > 0.0) x = std::min(x, root);
    }
  }
  return std::isinf(x) ? inf : std::sqrt(x);
}

double LensDistortion::max_valid_distorted_radius() const {
  const double r = max_valid_undistorted_radius();
  return std::isinf(r) ? r : forward(r);
}

double LensDistortion::inverse(double r_d, int max_iterations) const {
  if (r_d > max_valid_distorted_radius()) return std::numeric_limits<double>::quiet_NaN();
  const double r_max = max_valid_undistorted_radius();
  double r = std::min(r_d, 0.999 * r_max);
  for (int i = 0; i < max_iterations; ++i) {
    const double r2 = r * r;
    const double step = (forward(r) - r_d) / (1 + r2 * (3 * c1 + 5 * c2 * r2));
    r = std::clamp(r - step, 0.0, r_max);
    if (std::abs(step) < 1e-14) break;
  }
  return r;
}

}  // namespace vdfx::xr
