/// @file
/// @brief The radial kernel and distances of the RBF interpolation.
#include "effects/rbf_kernel.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "effects/coords.h"

namespace vdfx::effects {

RbfKernel RbfKernel::from(const InterpolationSettings& settings, double fps) {
  const double a = settings.exponent;
  const double c = settings.time_scale;
  if (!(a > kExponentMin && a < kExponentMax)) {
    std::ostringstream s;
    s << "RbfKernel: exponent " << a << " outside (" << kExponentMin << ", " << kExponentMax << ")";
    throw std::invalid_argument(s.str());
  }
  if (!(c > kTimeScaleMin && c <= kTimeScaleMax)) {
    std::ostringstream s;
    s << "RbfKernel: time_scale " << c << " outside (" << kTimeScaleMin << ", " << kTimeScaleMax
      << "]";
    throw std::invalid_argument(s.str());
  }
  if (!(fps > 0.0) || !std::isfinite(fps)) {
    std::ostringstream s;
    s << "RbfKernel: fps " << fps << " is not a positive number";
    throw std::invalid_argument(s.str());
  }
  RbfKernel k;
  k.alpha = a;
  k.kind = a == 1.0 ? RbfKernelKind::Linear
                    : (a == 2.0 ? RbfKernelKind::ThinPlate : RbfKernelKind::Power);
  k.distance = settings.distance;
  k.time_factor = (24.0 / fps) * c;
  k.outside = settings.outside;
  return k;
}

double RbfKernel::phi_of_d2(double d2) const {
  if (!(d2 > 0.0)) return 0.0;
  switch (kind) {
    case RbfKernelKind::Linear: return std::sqrt(d2);
    case RbfKernelKind::ThinPlate: return 0.5 * d2 * std::log(d2);
    case RbfKernelKind::Power: return std::exp(0.5 * alpha * std::log(d2));
  }
  return 0.0;
}

void RbfKernel::apply_phi(Eigen::Ref<Eigen::ArrayXd> d2) const {
  switch (kind) {
    case RbfKernelKind::Linear: d2 = d2.sqrt(); break;
    case RbfKernelKind::ThinPlate:
      // d^2 log d = 0.5 d2 log d2, continuous with value 0 at d = 0 (log 0 would give NaN).
      d2 = (d2 > 0.0).select(0.5 * d2 * d2.max(1e-300).log(), 0.0);
      break;
    case RbfKernelKind::Power:
      // d^alpha = exp(alpha/2 log d2); log 0 = -inf and exp(-inf) = 0 give phi(0) = 0 exactly.
      d2 = (0.5 * alpha * d2.log()).exp();
      break;
  }
}

double RbfKernel::angular_d2(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (distance == AngularDistance::Chordal) return (a - b).squaredNorm();
  const double s = angle_between(a, b);
  return s * s;
}

}  // namespace vdfx::effects
