/// @file
/// @brief Grain parameters and per-frame layout: RBF intensity and size, zero intensity costs
/// nothing, the refresh clock at 90 Hz, particle caching per refresh.
#include "effects/grain_layout.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace vdfx::effects {
namespace {

GrainEffect effect(GrainStyle style, std::vector<Keyframe> keys, std::uint64_t seed = 3) {
  GrainEffect e;
  e.style = style;
  e.seed = seed;
  e.keyframes = std::move(keys);
  return e;
}

Keyframe key(double az, double alt, std::int64_t frame, double intensity, double size) {
  return {{az, alt}, frame, {intensity, size}};
}

HeadPose looking_at(double az_deg) {
  HeadPose h;
  h.orientation =
      Eigen::AngleAxisd(-az_deg * kDegToRad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return h;
}

TEST(GrainRefresh, FloorOfDisplayTimeOverThePeriod) {
  EXPECT_EQ(grain_refresh_index(0, 20.0), 0);
  EXPECT_EQ(grain_refresh_index(19'999'999, 20.0), 0);
  EXPECT_EQ(grain_refresh_index(20'000'000, 20.0), 1);
  EXPECT_EQ(grain_refresh_index(-1, 20.0), -1);
  EXPECT_EQ(grain_refresh_index(-20'000'000, 20.0), -1);
  EXPECT_EQ(grain_refresh_index(-20'000'001, 20.0), -2);
  EXPECT_EQ(grain_refresh_index(1'000'000'000, 33.3), 30);  // 33.3 ms = 33 300 000 ns exactly
  EXPECT_THROW(grain_refresh_index(0, 0.0), std::invalid_argument);
}

TEST(GrainRefresh, At90HzThePatternChangesOnThe20msBoundariesAndNowhereElse) {
  // A 90 Hz session's display times (xr::Session: period round(1e9 / 90) ns) from a start that
  // is not a multiple of 20 ms. The layout's pattern (noise phase and particles) is compared
  // between successive frames.
  GrainSet shader({effect(GrainStyle::Surface, {key(0, 0, 0, 0.5, 1)})}, {}, 30.0);
  GrainEffect small_cloud = effect(GrainStyle::FreeCloud, {key(0, 0, 0, 0.5, 1)});
  small_cloud.settings.set(GrainSetting::Count, 100);
  GrainSet cloud({small_cloud}, {}, 30.0);
  const std::int64_t period = 11'111'111, start = 1'234'567'890;
  std::vector<GrainFrame> prev_s, prev_c;
  int changes = 0;
  for (int n = 0; n < 450; ++n) {  // five seconds
    const std::int64_t t = start + n * period;
    auto s = shader.layout({}, t, 0);
    auto c = cloud.layout({}, t, 0);
    ASSERT_EQ(s.size(), 1u);
    ASSERT_EQ(c.size(), 1u);
    if (n > 0) {
      const std::int64_t before = t - period;
      // Independent expectation: a multiple of 20 ms lies in (before, t].
      const bool boundary = (t / 20'000'000) != (before / 20'000'000);
      const bool noise_changed = s[0].noise_offset[0] != prev_s[0].noise_offset[0];
      const bool particles_changed = c[0].particle_key != prev_c[0].particle_key;
      ASSERT_EQ(noise_changed, boundary) << n;
      ASSERT_EQ(particles_changed, boundary) << n;
      changes += boundary;
    }
    prev_s = std::move(s);
    prev_c = std::move(c);
  }
  // 449 frame steps of 11.1 ms span 4.99 s: 249 or 250 boundaries, so at 90 Hz a pattern holds
  // for about two frames.
  EXPECT_GE(changes, 249);
  EXPECT_LE(changes, 250);
}

TEST(GrainLayout, IntensityAndSizeAreRbfParametersAtTheHeadsForwardDirection) {
  GrainSet set({effect(GrainStyle::Surface, {key(0, 0, 0, 0.2, 0.5), key(90, 0, 0, 0.8, 3.0)})}, {},
               30.0);
  auto at0 = set.layout(looking_at(0), 0, 0);
  auto at90 = set.layout(looking_at(90), 0, 0);
  ASSERT_EQ(at0.size(), 1u);
  ASSERT_EQ(at90.size(), 1u);
  EXPECT_NEAR(at0[0].params.intensity, 0.2, 1e-9);
  EXPECT_NEAR(at0[0].params.size, 0.5, 1e-9);
  EXPECT_NEAR(at90[0].params.intensity, 0.8, 1e-9);
  EXPECT_NEAR(at90[0].params.size, 3.0, 1e-9);
  // Size scales the lattice: cell = kGrainCellRad * sphere_m * size.
  EXPECT_NEAR(at90[0].cell_m, kGrainCellRad * 10.0 * 3.0, 1e-12);
  // In between the RBF blends; out of range values are clamped.
  const GrainParams mid = set.params(0, to_unit({45, 0}), 0);
  EXPECT_GT(mid.intensity, 0.2);
  EXPECT_LT(mid.intensity, 0.8);
  GrainSet over({effect(GrainStyle::Surface, {key(0, 0, 0, 1.0, 4.0), key(10, 0, 0, 1.0, 4.0),
                                              key(20, 0, 0, 0.0, 0.25)})},
                {}, 30.0);
  for (double az = -30; az < 60; az += 1) {
    const GrainParams p = over.params(0, to_unit({az, 0}), 0);
    ASSERT_GE(p.intensity, 0.0);
    ASSERT_LE(p.intensity, 1.0);
    ASSERT_GE(p.size, 0.25);
    ASSERT_LE(p.size, 4.0);
  }
}

TEST(GrainLayout, ZeroIntensityYieldsNoLayerAndVolumesCarryTheirRefreshKey) {
  GrainSet set({effect(GrainStyle::ObjectCloud, {key(0, 0, 0, 0.0, 1.0)}),
                effect(GrainStyle::FreeCloud, {}),  // no keyframes: neutral intensity 0
                effect(GrainStyle::Headset, {key(0, 0, 0, 0.0, 2.0)})},
               {}, 30.0);
  for (int n = 0; n < 20; ++n) EXPECT_TRUE(set.layout({}, n * 11'111'111, 0).empty());
  // The same effect with intensity above 0: one layer whose particles are named by the key of
  // (seed, refresh) and the effect's settings; nothing is sampled on the CPU.
  GrainEffect e = effect(GrainStyle::ObjectCloud, {key(0, 0, 0, 0.1, 1.0)});
  e.settings.set(GrainSetting::Count, 1234);
  GrainSet on({e}, {}, 30.0);
  const auto a = on.layout({}, 0, 0), b = on.layout({}, 11'111'111, 0);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(a[0].particle_key, grain_particle_key(e.seed, 0));
  EXPECT_EQ(b[0].particle_key, a[0].particle_key);  // the same 20 ms refresh
  EXPECT_EQ(a[0].settings, e.settings);
  EXPECT_NE(on.layout({}, 20'000'000, 0)[0].particle_key, a[0].particle_key);
}

TEST(GrainLayout, SeveralEffectsKeepFileOrderAndTheirOwnSeeds) {
  GrainSet set({effect(GrainStyle::Surface, {key(0, 0, 0, 0.3, 1)}, 1),
                effect(GrainStyle::Headset, {key(0, 0, 0, 0.0, 1)}, 2),
                effect(GrainStyle::Surface, {key(0, 0, 0, 0.6, 1)}, 3)},
               {}, 30.0);
  const auto frames = set.layout({}, 0, 0);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].effect, 0u);
  EXPECT_EQ(frames[1].effect, 2u);
  EXPECT_NE(frames[0].noise->permutation(), frames[1].noise->permutation());
  EXPECT_NE(frames[0].noise_offset[0], frames[1].noise_offset[0]);
}

}  // namespace
}  // namespace vdfx::effects
