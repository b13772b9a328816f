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
/// uniform direction), not by the study's interpolation between two random vertices; a point
/// that floating-point rounding puts on the wrong side of a boundary is clamped into its region
/// (moved by a relative 1e-12), never redrawn, so every particle costs the same fixed work.
/// Each particle: extent uniform in [0.5, 3] cm per axis times size, a uniform random
/// orientation (Shoemake's quaternion), brightness uniform in [0, 1], opacity uniform in
/// [kMinParticleOpacity, 1] (times the keyframed intensity when drawn).
///
/// The stream: particle i of a refresh is a function of (key, i) alone, its draw j the uniform
/// unit_uniform(hash32_draw(key, i, j)) (effects/grain_random.h), key = grain_particle_key(seed,
/// refresh). The GPU layer evaluates the same function in its vertex stage (xr/render/grain_gl.h,
/// effects/grain_shaders.cpp); grain_particle is its definition and the tests' reference.
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
/// A particle is in the object cloud's surrounding volume when its region draw's top 24 bits
/// reach this: ceil(kObjectShellShare * 2^24), an integer comparison on CPU and GPU alike.
inline constexpr std::uint32_t kObjectShellThreshold = 13421773u;

/// The draws j of one particle's stream (hash32_draw(key, i, j)), in the order the shader reads
/// them too.
enum ParticleDraw : std::uint32_t {
  kDrawRegion = 0,    //!< object_cloud: shell or surrounding volume
  kDrawPosition = 1,  //!< 3 draws: object_cloud (ln r, z, angle); free_cloud (rho^2, angle, y)
  kDrawExtent = 4,    //!< 3 draws, one per axis
  kDrawRotation = 7,  //!< 3 draws (Shoemake's u1, u2, u3)
  kDrawBrightness = 10,
  kDrawOpacity = 11,
};

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

/// The 32-bit key of one refresh's particles: SplitMix64's random_key(seed, "particle", refresh)
/// folded to 32 bits (effects/grain_random.h). Computed once per refresh, on the CPU.
std::uint32_t grain_particle_key(std::uint64_t seed, std::int64_t refresh);

/// Particle `index` of the refresh whose key is `key` (count plays no part: particle i is the same
/// whatever the count). Throws std::invalid_argument for a shader style.
GrainParticle grain_particle(GrainStyle style, const GrainSettings& settings, std::uint32_t key,
                             std::uint32_t index, double size = 1.0);

/// Samples the particles of one refresh: count = settings' count; identical for the same
/// (style, settings, seed, refresh, size), unrelated for another refresh index. Particle i is
/// grain_particle(style, settings, grain_particle_key(seed, refresh), i, size). For tests and
/// measurements: the renderer generates its particles on the GPU.
/// Throws std::invalid_argument for a shader style.
ParticleSet sample_grain_particles(GrainStyle style, const GrainSettings& settings,
                                   std::uint64_t seed, std::int64_t refresh, double size = 1.0);

}  // namespace vdfx::effects
