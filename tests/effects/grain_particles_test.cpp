/// @file
/// @brief The volumetric grain sampler (CPU): every particle in Vb - Vo, sizes, the documented
/// density laws, determinism per (seed, refresh index) and change at the next index.
#include "effects/grain_particles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "effects/coords.h"
#include "effects/grain_random.h"

namespace vdfx::effects {
namespace {

/// Kolmogorov-Smirnov distance of samples from the uniform distribution on [0, 1].
double ks_uniform(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    d = std::max({d, std::abs((i + 1) / n - x[i]), std::abs(x[i] - i / n)});
  return d;
}
/// The KS critical value at 0.1 % significance: a correct sampler fails one run in a thousand
/// seeds, and the seeds here are fixed.
double ks_limit(std::size_t n) {
  return 1.95 / std::sqrt(static_cast<double>(n));
}

GrainSettings object_settings(double sphere_m, double shell, int count) {
  GrainSettings s;
  s.set(GrainSetting::SphereM, sphere_m);
  s.set(GrainSetting::Shell, shell);
  s.set(GrainSetting::Count, count);
  return s;
}

GrainSettings free_settings(double radius, double height, int count) {
  GrainSettings s;
  s.set(GrainSetting::RadiusM, radius);
  s.set(GrainSetting::HeightM, height);
  s.set(GrainSetting::Count, count);
  return s;
}

TEST(GrainParticles, ObjectCloudParticlesLieInTheShellOrTheSurroundingVolume) {
  const GrainSettings s = object_settings(10.0, 1.1, 20000);
  const ParticleSet set = sample_grain_particles(GrainStyle::ObjectCloud, s, 7, 3);
  ASSERT_EQ(set.particles.size(), 20000u);
  for (const GrainParticle& p : set.particles) {
    const double r = p.centre.norm();
    // Vo is the ball r <= 10 (the video sphere); Vb the ball r <= 11; beyond it the surrounding
    // volume reaches 4 x 10 m.
    ASSERT_GT(r, 10.0);
    if (p.region == 0)
      ASSERT_LE(r, 11.0);
    else
      ASSERT_TRUE(r > 11.0 && r <= 40.0) << r;
    ASSERT_EQ(grain_region(GrainStyle::ObjectCloud, s, p.centre), p.region);
  }
  EXPECT_EQ(set.region_count[0] + set.region_count[1], 20000u);
}

TEST(GrainParticles, FreeCloudParticlesLieInTheCylinder) {
  const GrainSettings s = free_settings(2.0, 3.0, 20000);
  const ParticleSet set = sample_grain_particles(GrainStyle::FreeCloud, s, 11, 0);
  for (const GrainParticle& p : set.particles) {
    ASSERT_LE(std::hypot(p.centre.x(), p.centre.z()), 2.0);
    ASSERT_LE(std::abs(p.centre.y()), 1.5);
    ASSERT_EQ(p.region, 0);
  }
  // Outside points are rejected by the region test itself (the test would catch a sampler that
  // only checks one bound).
  EXPECT_EQ(grain_region(GrainStyle::FreeCloud, s, {2.01, 0, 0}), -1);
  EXPECT_EQ(grain_region(GrainStyle::FreeCloud, s, {0, 1.51, 0}), -1);
  EXPECT_EQ(grain_region(GrainStyle::ObjectCloud, object_settings(10, 1.1, 1), {0, 0, -10}), -1);
}

TEST(GrainParticles, SizesWithinHalfToThreeCentimetresTimesSize) {
  for (double size : {0.25, 1.0, 2.5, 4.0}) {
    const ParticleSet set =
        sample_grain_particles(GrainStyle::FreeCloud, free_settings(2, 3, 5000), 5, 1, size);
    double lo = 1e9, hi = 0;
    for (const GrainParticle& p : set.particles) {
      for (int a = 0; a < 3; ++a) {
        lo = std::min(lo, p.extent[a]);
        hi = std::max(hi, p.extent[a]);
      }
      ASSERT_NEAR(p.rotation.norm(), 1.0, 1e-12);
      ASSERT_GE(p.brightness, 0.0);
      ASSERT_LE(p.brightness, 1.0);
      ASSERT_GE(p.opacity, kMinParticleOpacity);
      ASSERT_LE(p.opacity, 1.0);
    }
    EXPECT_GE(lo, 0.005 * size) << size;
    EXPECT_LE(hi, 0.03 * size) << size;
    // The whole range is used (uniform per axis): within 1 % of both ends.
    EXPECT_LT(lo, 0.0053 * size) << size;
    EXPECT_GT(hi, 0.0297 * size) << size;
  }
}

TEST(GrainParticles, ObjectCloudDensityFallsAsTheCubeOfDistance) {
  // n(r) = N_v / (4 pi ln(r1/r0) r^3) in each region: ln r is uniform within a region, and the
  // shell holds kObjectShellShare of the particles.
  const GrainSettings s = object_settings(5.0, 1.5, 40000);
  const ParticleSet set = sample_grain_particles(GrainStyle::ObjectCloud, s, 21, 9);
  std::vector<double> t[2];
  Eigen::Vector3d mean_dir = Eigen::Vector3d::Zero();
  for (const GrainParticle& p : set.particles) {
    const auto [r0, r1] = object_cloud_radii(s, p.region);
    t[p.region].push_back(std::log(p.centre.norm() / r0) / std::log(r1 / r0));
    mean_dir += p.centre.normalized() / 40000.0;
  }
  for (int region = 0; region < 2; ++region)
    EXPECT_LT(ks_uniform(t[region]), ks_limit(t[region].size())) << region;
  // A uniform density (n constant, r^2 dr law) would fail the same check.
  std::vector<double> wrong;
  for (const GrainParticle& p : set.particles) {
    if (p.region != 1) continue;
    const auto [r0, r1] = object_cloud_radii(s, 1);
    const double r = p.centre.norm();
    wrong.push_back((r * r * r - r0 * r0 * r0) / (r1 * r1 * r1 - r0 * r0 * r0));
  }
  EXPECT_GT(ks_uniform(wrong), 10 * ks_limit(wrong.size()));
  // Shell share: binomial, 5 standard deviations.
  const double n = 40000, share = set.region_count[0] / n;
  EXPECT_NEAR(share, kObjectShellShare,
              5 * std::sqrt(kObjectShellShare * (1 - kObjectShellShare) / n));
  // Directions are uniform: the mean unit vector is near 0 (sd 1/sqrt(3N) per axis).
  EXPECT_LT(mean_dir.norm(), 5.0 / std::sqrt(3 * n));
  // Number density itself, from counts in two thin shells of the surrounding volume:
  // n(r_a) / n(r_b) = (r_b / r_a)^3.
  const auto count_in = [&](double a, double b) {
    double c = 0;
    for (const GrainParticle& p : set.particles) c += p.centre.norm() > a && p.centre.norm() <= b;
    return c / (4.0 / 3.0 * kPi * (b * b * b - a * a * a));
  };
  const double near = count_in(8.0, 9.0), far = count_in(18.0, 19.0);
  const double expected = std::pow(18.5 / 8.5, 3.0);
  EXPECT_NEAR(near / far, expected, 0.2 * expected);
}

TEST(GrainParticles, FreeCloudDensityIsUniform) {
  const GrainSettings s = free_settings(2.0, 3.0, 30000);
  const ParticleSet set = sample_grain_particles(GrainStyle::FreeCloud, s, 4, 2);
  std::vector<double> area, height, angle;
  for (const GrainParticle& p : set.particles) {
    area.push_back((p.centre.x() * p.centre.x() + p.centre.z() * p.centre.z()) / 4.0);
    height.push_back(p.centre.y() / 3.0 + 0.5);
    angle.push_back(std::atan2(p.centre.z(), p.centre.x()) / (2 * kPi) + 0.5);
  }
  EXPECT_LT(ks_uniform(area), ks_limit(area.size()));
  EXPECT_LT(ks_uniform(height), ks_limit(height.size()));
  EXPECT_LT(ks_uniform(angle), ks_limit(angle.size()));
}

TEST(GrainParticles, SameSeedAndRefreshGiveIdenticalParticlesTheNextIndexOthers) {
  const GrainSettings s = object_settings(10.0, 1.1, 5000);
  const ParticleSet a = sample_grain_particles(GrainStyle::ObjectCloud, s, 7, 42);
  const ParticleSet b = sample_grain_particles(GrainStyle::ObjectCloud, s, 7, 42);
  const ParticleSet next = sample_grain_particles(GrainStyle::ObjectCloud, s, 7, 43);
  const ParticleSet other_seed = sample_grain_particles(GrainStyle::ObjectCloud, s, 8, 42);
  ASSERT_EQ(a.particles.size(), b.particles.size());
  EXPECT_EQ(a.region_count[0], b.region_count[0]);
  EXPECT_EQ(a.region_count[1], b.region_count[1]);
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    ASSERT_EQ(a.particles[i].centre, b.particles[i].centre);
    ASSERT_EQ(a.particles[i].extent, b.particles[i].extent);
    ASSERT_EQ(a.particles[i].rotation, b.particles[i].rotation);
    ASSERT_EQ(a.particles[i].brightness, b.particles[i].brightness);
  }
  // The next index: the per-region counts differ (each particle picks its region at random) and
  // no particle keeps its position.
  EXPECT_NE(a.region_count[0], next.region_count[0]);
  std::size_t same = 0, same_seed = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    same += a.particles[i].centre == next.particles[i].centre;
    same_seed += a.particles[i].centre == other_seed.particles[i].centre;
  }
  EXPECT_EQ(same, 0u);
  EXPECT_EQ(same_seed, 0u);
  EXPECT_THROW(sample_grain_particles(GrainStyle::Surface, s, 7, 0), std::invalid_argument);
}

TEST(GrainParticles, TheStreamIsTheDocumentedLowbias32WithExactFloatUniforms) {
  // Values from an independent evaluation of the formula in effects/grain_random.h (x ^= x >> 16;
  // x *= 0x7feb352d; x ^= x >> 15; x *= 0x846ca68b; x ^= x >> 16, modulo 2^32).
  EXPECT_EQ(hash32(0u), 0u);
  EXPECT_EQ(hash32(1u), 0x688990c0u);
  EXPECT_EQ(hash32(2u), 0xd1132181u);
  EXPECT_EQ(hash32(0xdeadbeefu), 0xe628c683u);
  EXPECT_EQ(hash32_draw(0x12345678u, 7u, 3u), 0x85e5a89du);
  // 24-bit uniforms: in [0, 1), and the same number in float as in double.
  EXPECT_EQ(unit_uniform(0u), 0.0);
  EXPECT_EQ(unit_uniform(0xffffffffu), 1.0 - 0x1.0p-24);
  for (std::uint32_t h : {0x12345678u, 0x9abcdef0u, 0xffffff00u})
    EXPECT_EQ(static_cast<double>(static_cast<float>(unit_uniform(h))), unit_uniform(h));
  EXPECT_EQ(kObjectShellThreshold,
            static_cast<std::uint32_t>(std::ceil(kObjectShellShare * 0x1.0p24)));
}

TEST(GrainParticles, AParticleIsAFunctionOfKeyAndIndexAloneWhateverTheCount) {
  const GrainSettings few = object_settings(10.0, 1.1, 100),
                      many = object_settings(10.0, 1.1, 5000);
  const ParticleSet a = sample_grain_particles(GrainStyle::ObjectCloud, few, 7, 42);
  const ParticleSet b = sample_grain_particles(GrainStyle::ObjectCloud, many, 7, 42);
  const std::uint32_t key = grain_particle_key(7, 42);
  for (std::uint32_t i = 0; i < 100; ++i) {
    const GrainParticle p = grain_particle(GrainStyle::ObjectCloud, few, key, i);
    ASSERT_EQ(a.particles[i].centre, p.centre) << i;
    ASSERT_EQ(b.particles[i].centre, p.centre) << i;
    ASSERT_EQ(b.particles[i].extent, p.extent) << i;
    ASSERT_EQ(b.particles[i].opacity, p.opacity) << i;
  }
  EXPECT_THROW(grain_particle(GrainStyle::Headset, few, key, 0), std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
