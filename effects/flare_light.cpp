/// @file
/// @brief Great-circle interpolation of light tracks.
#include "effects/flare_light.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

Eigen::Vector3d slerp_unit(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) {
  const double omega = angle_between(a, b);
  // Below ~1e-6 rad sin(omega) loses its digits; the chord and the arc agree to omega^2 there.
  if (omega < 1e-6) return ((1.0 - t) * a + t * b).normalized();
  const double s = std::sin(omega);
  return ((std::sin((1.0 - t) * omega) / s) * a + (std::sin(t * omega) / s) * b).normalized();
}

Eigen::Vector3d light_on_track(std::span<const LightSample> track, std::int64_t frame) {
  if (track.empty()) throw std::invalid_argument("light_on_track: empty track");
  if (frame <= track.front().frame) return to_unit(track.front().direction);
  if (frame >= track.back().frame) return to_unit(track.back().direction);
  const auto hi =
      std::upper_bound(track.begin(), track.end(), frame,
                       [](std::int64_t f, const LightSample& s) { return f < s.frame; });
  const LightSample& b = *hi;
  const LightSample& a = *(hi - 1);
  const double t = static_cast<double>(frame - a.frame) / static_cast<double>(b.frame - a.frame);
  return slerp_unit(to_unit(a.direction), to_unit(b.direction), t);
}

}  // namespace vdfx::effects
