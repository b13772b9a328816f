/// @file
/// @brief grain_particle: regions, the 1/r^3 radial law, particle shape and shade.
#include "effects/grain_particles.h"

#include <cmath>
#include <stdexcept>

#include "effects/coords.h"
#include "effects/grain_random.h"

namespace vdfx::effects {
namespace {

constexpr std::uint64_t kParticleStream = 0x7061727469636c65;  // "particle"
/// Relative margin by which a point rounded onto the wrong side of a boundary is moved inside.
constexpr double kClampMargin = 1e-12;

/// The draws of one particle: u(j) = unit_uniform(hash32_draw(key, i, j)).
struct Draws {
  std::uint32_t key, index;
  std::uint32_t bits(std::uint32_t j) const { return hash32_draw(key, index, j); }
  double u(std::uint32_t j) const { return unit_uniform(bits(j)); }
};

/// Shoemake, "Uniform random rotations" (Graphics Gems III, 1992): a uniform unit quaternion from
/// three uniforms.
Eigen::Vector4d uniform_rotation(const Draws& d) {
  const double u1 = d.u(kDrawRotation), u2 = d.u(kDrawRotation + 1), u3 = d.u(kDrawRotation + 2);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return {a * std::sin(2.0 * kPi * u2), a * std::cos(2.0 * kPi * u2), b * std::sin(2.0 * kPi * u3),
          b * std::cos(2.0 * kPi * u3)};
}

/// Scales p (a radius of `n`) so that its radius lies in (lo, hi]: a no-op unless rounding put
/// it on a boundary's wrong side.
Eigen::Vector3d clamp_radius(const Eigen::Vector3d& p, double n, double lo, double hi) {
  if (n <= lo) return p * (lo * (1.0 + kClampMargin) / n);
  if (n > hi) return p * (hi * (1.0 - kClampMargin) / n);
  return p;
}

/// A point of one region, by the inverse CDF of its law, clamped into the region.
Eigen::Vector3d sample_point(GrainStyle style, const GrainSettings& s, int region, const Draws& d) {
  const double u0 = d.u(kDrawPosition), u1 = d.u(kDrawPosition + 1), u2 = d.u(kDrawPosition + 2);
  if (style == GrainStyle::FreeCloud) {
    const double radius = s.get(GrainSetting::RadiusM);
    const double rho = radius * std::sqrt(u0), phi = 2.0 * kPi * u1;
    const double y = (u2 - 0.5) * s.get(GrainSetting::HeightM);  // u2 < 1: |y| < height / 2
    const Eigen::Vector3d p(rho * std::cos(phi), y, rho * std::sin(phi));
    const double n = std::hypot(p.x(), p.z());
    return n > radius ? Eigen::Vector3d(p.x() * radius * (1.0 - kClampMargin) / n, y,
                                        p.z() * radius * (1.0 - kClampMargin) / n)
                      : p;
  }
  // n(r) ~ 1/r^3 makes ln r uniform on (ln r0, ln r1]; 1 - u is in (0, 1].
  const auto [r0, r1] = object_cloud_radii(s, region);
  const double r = r0 * std::exp((1.0 - u0) * std::log(r1 / r0));
  const double z = 1.0 - 2.0 * u1, phi = 2.0 * kPi * u2;
  const double sz = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Eigen::Vector3d p = r * Eigen::Vector3d(sz * std::cos(phi), z, sz * std::sin(phi));
  return clamp_radius(p, p.norm(), r0, r1);
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

std::uint32_t grain_particle_key(std::uint64_t seed, std::int64_t refresh) {
  return fold32(random_key(seed, kParticleStream, refresh));
}

GrainParticle grain_particle(GrainStyle style, const GrainSettings& s, std::uint32_t key,
                             std::uint32_t index, double size) {
  if (!is_volumetric(style))
    throw std::invalid_argument("grain_particle: " + std::string(grain_style_name(style)) +
                                " is a shader style");
  const Draws d{key, index};
  GrainParticle p;
  p.region =
      style == GrainStyle::ObjectCloud && (d.bits(kDrawRegion) >> 8) >= kObjectShellThreshold;
  p.centre = sample_point(style, s, p.region, d);
  for (std::uint32_t a = 0; a < 3; ++a)
    p.extent[a] = size * (kParticleMinExtentM +
                          (kParticleMaxExtentM - kParticleMinExtentM) * d.u(kDrawExtent + a));
  p.rotation = uniform_rotation(d);
  p.brightness = d.u(kDrawBrightness);
  p.opacity = kMinParticleOpacity + (1.0 - kMinParticleOpacity) * d.u(kDrawOpacity);
  return p;
}

}  // namespace vdfx::effects
