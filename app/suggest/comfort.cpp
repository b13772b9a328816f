/// @file
/// @brief The comfort vignette's mapping (comfort.h).
#include "app/suggest/comfort.h"

#include <algorithm>

namespace vdfx::app::suggest {

double comfort_radius_deg(double speed, double strength) {
  const double w = std::clamp(
      (speed - kComfortStartDegPerS) / (kComfortFullDegPerS - kComfortStartDegPerS), 0.0, 1.0);
  return kComfortOpenRadiusDeg - strength * w * (kComfortOpenRadiusDeg - kComfortMinRadiusDeg);
}

std::vector<double> look_ahead_max(const std::vector<double>& speed, std::int64_t lead) {
  const auto n = static_cast<std::int64_t>(speed.size());
  std::vector<double> out(speed.size(), 0.0);
  for (std::int64_t i = 0; i < n; ++i) {
    const auto first = speed.begin() + std::max<std::int64_t>(0, i - lead);
    const auto last = speed.begin() + std::min<std::int64_t>(n, i + lead + 1);
    out[static_cast<std::size_t>(i)] = *std::max_element(first, last);
  }
  return out;
}

}  // namespace vdfx::app::suggest
