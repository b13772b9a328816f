/// @file
/// @brief StackInterpolator: active effects only, clamping and tint renormalisation.
#include "effects/stack_interpolator.h"

#include <gtest/gtest.h>

namespace vdfx::effects {
namespace {

TEST(StackInterpolator, EffectsWithoutKeyframesStayNeutralAndInactive) {
  std::vector<EffectTrack> tracks(2);
  tracks[0].type = EffectType::Exposure;
  tracks[0].keyframes = {{{0, 0}, 0, {2.0}}, {{90, 0}, 0, {-1.0}}};
  tracks[1].type = EffectType::Blur;  // a track with no keyframes
  const StackInterpolator s(tracks, {}, 30.0);
  EXPECT_TRUE(s.active(EffectType::Exposure));
  EXPECT_FALSE(s.active(EffectType::Blur));
  EXPECT_FALSE(s.active(EffectType::Tint));
  EXPECT_EQ(s.interpolator(EffectType::Vignette), nullptr);
  const StackParams p = s.evaluate(Direction{90, 0}, 0);
  EXPECT_NEAR(p.exposure_stops, -1.0, 1e-9);
  EXPECT_NEAR(s.evaluate(Direction{0, 0}, 0).exposure_stops, 2.0, 1e-9);
  for (EffectType t : {EffectType::Blur, EffectType::Tint, EffectType::Saturation,
                       EffectType::Contrast, EffectType::Vignette})
    EXPECT_TRUE(p.is_neutral(t)) << effect_name(t);
}

TEST(StackInterpolator, ClampsOvershootAndRenormalisesTint) {
  std::vector<EffectTrack> tracks(2);
  tracks[0].type = EffectType::Tint;
  tracks[0].keyframes = {{{0, 0}, 0, {2.0, 1.0, 0.5}},
                         {{120, 0}, 0, {0.5, 1.0, 2.0}},
                         {{-120, 0}, 0, {1.0, 1.0, 1.0}}};
  tracks[1].type = EffectType::Contrast;
  tracks[1].interpolation = InterpolationSettings{3.0, 1.0, AngularDistance::Chordal};
  // Values at the range ends: a cubic kernel overshoots between them.
  tracks[1].keyframes = {{{0, 0}, 0, {4.0}},
                         {{10, 0}, 0, {4.0}},
                         {{20, 0}, 0, {0.0}},
                         {{30, 0}, 0, {0.0}},
                         {{40, 0}, 0, {4.0}}};
  const StackInterpolator s(tracks, {}, 30.0);
  for (double az = -180; az < 180; az += 2.5) {
    const StackParams p = s.evaluate(Direction{az, 10}, 0);
    const Eigen::Vector3d& g = p.tint_gain;
    EXPECT_NEAR(kLumaR * g.x() + kLumaG * g.y() + kLumaB * g.z(), 1.0, 1e-12) << az;
    EXPECT_GE(p.contrast, 0.0);
    EXPECT_LE(p.contrast, 4.0);
  }
  const StackParams at0 = s.evaluate(Direction{0, 0}, 0);
  EXPECT_NEAR(at0.tint_gain.x() / at0.tint_gain.z(), 4.0, 1e-9);
}

TEST(StackInterpolator, RejectsTwoTracksForOneEffect) {
  std::vector<EffectTrack> tracks(2);
  tracks[0].type = tracks[1].type = EffectType::Saturation;
  EXPECT_THROW(StackInterpolator(tracks, {}, 30.0), std::invalid_argument);
}

TEST(StackInterpolator, BuildsFromSolvedInterpolators) {
  StackInterpolator::Solutions sol;
  const std::vector<Keyframe> k = {{{0, 0}, 0, {1.5}}};
  sol[static_cast<size_t>(EffectType::Saturation)] =
      std::make_shared<const RbfInterpolator>(k, 1, InterpolationSettings{}, 30.0);
  sol[static_cast<size_t>(EffectType::Contrast)] = std::make_shared<const RbfInterpolator>(
      std::vector<Keyframe>{}, 1, InterpolationSettings{}, 30.0, std::vector<double>{1.0});
  const StackInterpolator s(sol);
  EXPECT_TRUE(s.active(EffectType::Saturation));
  EXPECT_FALSE(s.active(EffectType::Contrast));  // empty counts as inactive
  EXPECT_DOUBLE_EQ(s.evaluate(Direction{45, 45}, 9).saturation, 1.5);
}

}  // namespace
}  // namespace vdfx::effects
