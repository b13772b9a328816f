/// @file
/// @brief The volumetric grain sampler (object_cloud, free_cloud): particles in Vb - Vo, drawn
/// from (seed, refresh index) alone. docs/grain.md, "Volumetric grain".
///
/// Positions are relative to the head (cyclopean) position, axes LOCAL's: the renderer adds the
/// head position of the frame, so the volumes stay centred on the viewer as the video sphere does
/// and keep their world orientation when the head turns.
///
/// Regions and densities (r = distance from the head, R = sphere_m, s = shell):
/// - object_cloud: Vo = the ball r <= R (the video sphere as the object), Vb = Vo scaled by s.
///   The shell R < r <= sR holds each particle with probability kObjectShellShare; the rest go to
///   the surrounding volume sR < r <= kObjectFarFactor R (infinite-depth grain). In both the
///   number density falls as 1/r^3: n(r) = N_v / (4 pi ln(r1 / r0) r^3), so every octave of
///   distance holds the same number of grains per solid angle, and a nearer object's shell is
///   denser. ln r is therefore uniform within each region.
/// - free_cloud: Vo is empty, Vb the cylinder x^2 + z^2 <= radius_m^2, |y| <= height_m / 2;
///   uniform density N / (pi radius^2 height).
/// Sampling: the region is sampled directly (inverse CDF of the law above: radius, then a
/// uniform direction), not by the study's interpolation between two random vertices; a point is
/// redrawn only when floating-point rounding puts it on the wrong side of a boundary.
/// Each particle: extent uniform in [0.5, 3] cm per axis times size, a uniform random
/// orientation (Shoemake's quaternion), brightness uniform in [0, 1], opacity uniform in
/// [kMinParticleOpacity, 1] (times the keyframed intensity when drawn).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "effects/grain.h"

namespace vdfx::effects {

inline constexpr double kParticleMinExtentM = 0.005;
inline constexpr double kParticleMaxExtentM = 0.03;
inline constexpr double kMinParticleOpacity = 0.25;
inline constexpr double kObjectShellShare = 0.8;  //!< expected share of particles in the shell
inline constexpr double kObjectFarFactor = 4.0;   //!< surrounding volume's outer radius / R

struct GrainParticle {
  Eigen::Vector3d centre;    //!< metres, relative to the head position, LOCAL axes
  Eigen::Vector3d extent;    //!< full size along the particle's own axes, metres
  Eigen::Vector4d rotation;  //!< unit quaternion (x, y, z, w): particle axes -> LOCAL
  double brightness = 0.5;   //!< grey value drawn, 0..1
  double opacity = 1.0;      //!< kMinParticleOpacity..1
  int region = 0;            //!< 0: shell (free_cloud: the cylinder), 1: surrounding volume
};

struct ParticleSet {
  std::int64_t refresh = 0;
  std::vector<GrainParticle> particles;
  std::size_t region_count[2] = {0, 0};  //!< particles per region
};

/// Which region a point (relative to the head) lies in for a volumetric style: 0 or 1 as
/// GrainParticle::region, -1 outside Vb - Vo. Boundaries: the inner one is excluded, the outer
/// one included.
int grain_region(GrainStyle style, const GrainSettings& settings, const Eigen::Vector3d& p);

/// The inner and outer radius of an object_cloud region (0 shell, 1 surrounding volume).
std::pair<double, double> object_cloud_radii(const GrainSettings& settings, int region);

/// Samples the particles of one refresh: count = settings' count; identical for the same
/// (style, settings, seed, refresh, size), unrelated for another refresh index.
/// Throws std::invalid_argument for a shader style.
ParticleSet sample_grain_particles(GrainStyle style, const GrainSettings& settings,
                                   std::uint64_t seed, std::int64_t refresh, double size = 1.0);

}  // namespace vdfx::effects
