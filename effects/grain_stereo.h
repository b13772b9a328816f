/// @file
/// @brief What each grain style asks of the eyes (flare-grain.md, stereo rule 3): the distances
/// its grains sit at, and the vergence angle and on-screen disparity of those distances at a
/// headset's IPD. docs/grain.md tabulates them for the bundled profiles.
#pragma once

#include "effects/grain.h"

namespace vdfx::effects {

/// Distances from the head at which a style's visible grains lie (metres): headset and surface a
/// single distance (plane_m on the view axis, sphere_m); object_cloud from sphere_m to the
/// surrounding volume's outer radius; free_cloud from where the near fade lets particles show
/// (kParticleNearFadeStartM) to the farthest point of the cylinder.
struct GrainDepthRange {
  double near_m = 0.0;
  double far_m = 0.0;
};
GrainDepthRange grain_depth_range(GrainStyle style, const GrainSettings& settings);

/// A point straight ahead at distance d: vergence 2 atan(ipd / 2d), and the horizontal offset
/// between its images in the two eyes relative to a point at infinity, ipd / d in tangent units,
/// times the eye's pixels per tangent unit.
struct Disparity {
  double vergence_deg = 0.0;
  double pixels = 0.0;
};
Disparity disparity_at(double distance_m, double ipd_m, double px_per_tangent);

}  // namespace vdfx::effects
