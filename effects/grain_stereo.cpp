/// @file
/// @brief Grain depth ranges and the disparity of a distance.
#include "effects/grain_stereo.h"

#include <cmath>

#include "effects/coords.h"
#include "effects/grain_particles.h"
#include "effects/grain_shaders.h"

namespace vdfx::effects {

GrainDepthRange grain_depth_range(GrainStyle style, const GrainSettings& s) {
  switch (style) {
    case GrainStyle::Headset: return {s.get(GrainSetting::PlaneM), s.get(GrainSetting::PlaneM)};
    case GrainStyle::Surface: return {s.get(GrainSetting::SphereM), s.get(GrainSetting::SphereM)};
    case GrainStyle::ObjectCloud:
      return {object_cloud_radii(s, 0).first, object_cloud_radii(s, 1).second};
    case GrainStyle::FreeCloud: {
      const double r = s.get(GrainSetting::RadiusM), h = 0.5 * s.get(GrainSetting::HeightM);
      return {kParticleNearFadeStartM, std::sqrt(r * r + h * h)};
    }
  }
  return {};
}

Disparity disparity_at(double d, double ipd, double px_per_tangent) {
  return {2.0 * std::atan(0.5 * ipd / d) * kRadToDeg, ipd / d * px_per_tangent};
}

}  // namespace vdfx::effects
