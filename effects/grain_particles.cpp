/// @file
/// @brief sample_grain_particles: regions, the 1/r^3 radial law, particle shape and shade.
#include "effects/grain_particles.h"

#include <cmath>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "effects/coords.h"
#include "effects/grain_random.h"

namespace vdfx::effects {
namespace {

constexpr std::uint64_t kParticleStream = 0x7061727469636c65;  // "particle"

Eigen::Vector3d uniform_direction(RandomStream& rng) {
  const double z = 1.0 - 2.0 * rng.uniform();
  const double phi = 2.0 * kPi * rng.uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), z, s * std::sin(phi)};
}

/// Shoemake, "Uniform random rotations" (Graphics Gems III, 1992): a uniform unit quaternion from
/// three uniforms.
Eigen::Vector4d uniform_rotation(RandomStream& rng) {
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return {a * std::sin(2.0 * kPi * u2), a * std::cos(2.0 * kPi * u2), b * std::sin(2.0 * kPi * u3),
          b * std::cos(2.0 * kPi * u3)};
}

/// A point of one region, by the inverse CDF of its law.
Eigen::Vector3d sample_point(GrainStyle style, const GrainSettings& s, int region,
                             RandomStream& rng) {
  if (style == GrainStyle::FreeCloud) {
    const double rho = s.get(GrainSetting::RadiusM) * std::sqrt(rng.uniform());
    const double phi = 2.0 * kPi * rng.uniform();
    const double y = (rng.uniform() - 0.5) * s.get(GrainSetting::HeightM);
    return {rho * std::cos(phi), y, rho * std::sin(phi)};
  }
  // n(r) ~ 1/r^3 makes ln r uniform on (ln r0, ln r1]; 1 - u is in (0, 1].
  const auto [r0, r1] = object_cloud_radii(s, region);
  const double r = r0 * std::exp((1.0 - rng.uniform()) * std::log(r1 / r0));
  return r * uniform_direction(rng);
}

}  // namespace

std::pair<double, double> object_cloud_radii(const GrainSettings& s, int region) {
  const double R = s.get(GrainSetting::SphereM), shell = s.get(GrainSetting::Shell);
  return region == 0 ? std::pair{R, shell * R} : std::pair{shell * R, kObjectFarFactor * R};
}

int grain_region(GrainStyle style, const GrainSettings& s, const Eigen::Vector3d& p) {
  if (style == GrainStyle::FreeCloud) {
    const double rho = s.get(GrainSetting::RadiusM), h = s.get(GrainSetting::HeightM);
    const bool in = p.x() * p.x() + p.z() * p.z() <= rho * rho && std::abs(p.y()) <= 0.5 * h;
    return in ? 0 : -1;
  }
  if (style != GrainStyle::ObjectCloud) return -1;
  const double r = p.norm();
  for (int region = 0; region < 2; ++region) {
    const auto [r0, r1] = object_cloud_radii(s, region);
    if (r > r0 && r <= r1) return region;
  }
  return -1;
}

ParticleSet sample_grain_particles(GrainStyle style, const GrainSettings& s, std::uint64_t seed,
                                   std::int64_t refresh, double size) {
  if (!is_volumetric(style))
    throw std::invalid_argument("sample_grain_particles: " + std::string(grain_style_name(style)) +
                                " is a shader style");
  ParticleSet out;
  out.refresh = refresh;
  const auto count = static_cast<std::size_t>(s.get(GrainSetting::Count));
  out.particles.resize(count);
  // Counter-based: particle i draws from its own stream, so the set is the same however the work
  // is split between threads (and a GPU could generate it the same way).
  const std::uint64_t key = random_key(seed, kParticleStream, refresh);
  cv::parallel_for_(cv::Range(0, static_cast<int>(count)), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      GrainParticle& p = out.particles[static_cast<std::size_t>(i)];
      RandomStream rng(mix64(key ^ static_cast<std::uint64_t>(i)));
      p.region = style == GrainStyle::ObjectCloud && rng.uniform() >= kObjectShellShare ? 1 : 0;
      do {
        p.centre = sample_point(style, s, p.region, rng);
      } while (grain_region(style, s, p.centre) != p.region);
      for (int a = 0; a < 3; ++a)
        p.extent[a] = size * rng.uniform(kParticleMinExtentM, kParticleMaxExtentM);
      p.rotation = uniform_rotation(rng);
      p.brightness = rng.uniform();
      p.opacity = rng.uniform(kMinParticleOpacity, 1.0);
    }
  });
  for (const GrainParticle& p : out.particles) ++out.region_count[p.region];
  return out;
}

}  // namespace vdfx::effects
