/// @file
/// @brief require_finite.
#include "app/cli/finite_params.h"

#include <cmath>
#include <cstdio>

#include "io/input_error.h"

namespace vdfx::app {

void require_finite(const effects::StackParams& p, const std::string& sidecar_name,
                    const effects::Direction& at, std::int64_t frame) {
  const double values[] = {p.blur_sigma_deg, p.tint_gain.x(),       p.tint_gain.y(),
                           p.tint_gain.z(),  p.exposure_stops,      p.saturation,
                           p.contrast,       p.vignette_radius_deg, p.vignette_falloff_deg};
  for (const double v : values) {
    if (std::isfinite(v)) continue;
    char where[96];
    std::snprintf(where, sizeof where, "%.6g,%.6g,%lld", at.azimuth_deg, at.altitude_deg,
                  static_cast<long long>(frame));
    throw io::InputError(sidecar_name + ": the effects evaluate to a value that is not finite at " +
                         where + " (the file's numbers are beyond what the interpolation can " +
                         "represent); nothing was rendered");
  }
}

}  // namespace vdfx::app
