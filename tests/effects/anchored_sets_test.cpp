/// @file
/// @brief Anchors honoured where effects are evaluated: the stack, the flares and the grain each
/// interpolate at the view turned into their anchor's frame (world: the camera's rotation undone;
/// a track: the subject brought back to where it stood), a fixed flare light stays in its
/// anchor's frame, effects sharing an anchor agree with ones resolved apart, and an anchor that
/// names what the sources lack is refused.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "effects/anchor_sources.h"
#include "effects/flare_set.h"
#include "effects/grain_layout.h"
#include "effects/stack_interpolator.h"
#include "effects/view_camera.h"

namespace vdfx::effects {
namespace {

constexpr int kFrames = 8;
constexpr double kTurnDegPerFrame = 40.0;  // the camera turns right

/// q_f of a camera turned right by `deg`: a direction of the video frame at azimuth a is at
/// azimuth a + deg in the world (a turn about +y by -deg).
Quat yaw(double deg) {
  return from_eigen(
      Eigen::Quaterniond(Eigen::AngleAxisd(-deg * kDegToRad, Eigen::Vector3d::UnitY())));
}

CameraMotion turning_camera() {
  CameraMotion c;
  c.source = CameraMotion::Source::Given;
  for (int f = 0; f < kFrames; ++f) c.orientation.push_back(yaw(kTurnDegPerFrame * f));
  return c;
}

/// Where a world direction is in the video frame at frame f of turning_camera().
Direction video_of_world(const Direction& w, double f) {
  return {wrap_azimuth_deg(w.azimuth_deg - kTurnDegPerFrame * f), w.altitude_deg};
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kRadToDeg;
}

const Direction kWindow{31.0, 5.0}, kBehind{-149.0, -5.0};

/// Exposure -1.2 stops at the window and 0 behind it, both at frame 0 (constant in time).
EffectTrack window_exposure(Anchor anchor) {
  EffectTrack t;
  t.type = EffectType::Exposure;
  t.anchor = std::move(anchor);
  t.keyframes = {{kWindow, 0, {-1.2}}, {kBehind, 0, {0.0}}};
  return t;
}

const Anchor kWorld{Anchor::Kind::World, {}};

TEST(AnchoredStack, AWorldAnchoredExposureStaysOnTheWindowWhileTheCameraTurns) {
  const CameraMotion camera = turning_camera();
  const StackInterpolator anchored({window_exposure(kWorld)}, {}, 30.0, {&camera, {}});
  const StackInterpolator fixed({window_exposure({})}, {}, 30.0);
  double video_worst = 0.0;
  for (int f = 0; f < kFrames; ++f) {
    const Direction at = video_of_world(kWindow, f);
    EXPECT_NEAR(anchored.evaluate(at, f).exposure_stops, -1.2, 1e-9) << "frame " << f;
    video_worst = std::max(video_worst, std::abs(fixed.evaluate(at, f).exposure_stops + 1.2));
  }
  // The video anchor (today's behaviour) leaves the window: near half a turn on, it is about
  // neutral there.
  EXPECT_GT(video_worst, 1.0);
  // At frame 0 (q_0 = identity) both agree everywhere.
  for (double az = -180.0; az < 180.0; az += 15.0)
    EXPECT_NEAR(anchored.evaluate(Direction{az, 10.0}, 0).exposure_stops,
                fixed.evaluate(Direction{az, 10.0}, 0).exposure_stops, 1e-12);
}

TEST(AnchoredStack, EachEffectTurnsByItsOwnAnchorAndSharedAnchorsAgreeWithSeparateOnes) {
  const CameraMotion camera = turning_camera();
  EffectTrack contrast;
  contrast.type = EffectType::Contrast;
  contrast.anchor = kWorld;
  contrast.keyframes = {{kWindow, 0, {2.0}}, {kBehind, 0, {0.5}}};
  EffectTrack saturation;  // video: fixed in the frame
  saturation.type = EffectType::Saturation;
  saturation.keyframes = {{kWindow, 0, {3.0}}, {kBehind, 0, {0.2}}};
  const StackInterpolator both({window_exposure(kWorld), contrast, saturation}, {}, 30.0,
                               {&camera, {}});
  const StackInterpolator exposure_only({window_exposure(kWorld)}, {}, 30.0, {&camera, {}});
  const StackInterpolator contrast_only({contrast}, {}, 30.0, {&camera, {}});
  const StackInterpolator saturation_only({saturation}, {}, 30.0);
  EXPECT_FALSE(both.anchor(EffectType::Contrast).identity());
  EXPECT_TRUE(both.anchor(EffectType::Saturation).identity());
  for (int f = 0; f < kFrames; ++f)
    for (double az = -170.0; az < 180.0; az += 20.0) {
      const Direction d{az, -20.0 + az / 10.0};
      const StackParams p = both.evaluate(d, f);
      EXPECT_EQ(p.exposure_stops, exposure_only.evaluate(d, f).exposure_stops);
      EXPECT_EQ(p.contrast, contrast_only.evaluate(d, f).contrast);
      EXPECT_EQ(p.saturation, saturation_only.evaluate(d, f).saturation);
    }
  EXPECT_NEAR(both.evaluate(video_of_world(kWindow, 3), 3).contrast, 2.0, 1e-9);
  EXPECT_NEAR(both.evaluate(kWindow, 3).saturation, 3.0, 1e-9);
}

TEST(AnchoredStack, ATrackAnchoredEffectFollowsTheSubject) {
  // The actor walks from azimuth -60 to +60 over frames 2..8 (held before and after the span).
  SubjectTrack actor{"actor", {}};
  for (int f = 2; f <= 8; ++f) actor.points.push_back({f, {-60.0 + 20.0 * (f - 2), 3.0}, 1.0});
  EffectTrack sat;
  sat.type = EffectType::Saturation;
  sat.anchor = Anchor{Anchor::Kind::Track, "actor"};
  // Relative to the actor as she stood at frame 2: on her, and away from her.
  sat.keyframes = {{{-60.0, 3.0}, 0, {2.5}}, {{120.0, -3.0}, 0, {0.5}}};
  const std::vector<SubjectTrack> tracks{actor};
  const StackInterpolator s({sat}, {}, 30.0, {nullptr, tracks});
  for (int f = 0; f <= 11; ++f) {
    const Direction on = actor.points[static_cast<std::size_t>(std::clamp(f - 2, 0, 6))].direction;
    EXPECT_NEAR(s.evaluate(on, f).saturation, 2.5, 1e-9) << "frame " << f;
  }
  // Where she stood at first is no longer where the effect is once she walked off.
  EXPECT_LT(s.evaluate(Direction{-60.0, 3.0}, 8).saturation, 2.0);
}

TEST(AnchoredStack, AnAnchorNamingWhatTheSourcesLackIsRefused) {
  EXPECT_THROW(StackInterpolator({window_exposure(kWorld)}, {}, 30.0), std::invalid_argument);
  EffectTrack t = window_exposure(Anchor{Anchor::Kind::Track, "nobody"});
  try {
    StackInterpolator({t}, {}, 30.0, {});
    FAIL() << "no track named nobody";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("track:nobody"), std::string::npos) << e.what();
  }
  // An anchored track without keyframes is inactive: nothing to resolve.
  t.keyframes.clear();
  EXPECT_FALSE(StackInterpolator({t}, {}, 30.0).active(EffectType::Exposure));
}

HeadPose looking_at(const Direction& d) {
  HeadPose h;
  h.orientation = pose_rotation({d, 0.0});
  return h;
}

/// A camera that turns about all three axes, differently at each of `frames` frames.
CameraMotion tumbling_camera(int frames) {
  CameraMotion c;
  c.source = CameraMotion::Source::Given;
  for (int f = 0; f < frames; ++f)
    c.orientation.push_back(from_eigen(Eigen::AngleAxisd(0.7 * f, Eigen::Vector3d::UnitY()) *
                                       Eigen::AngleAxisd(0.3 + 0.2 * f, Eigen::Vector3d::UnitX()) *
                                       Eigen::AngleAxisd(-0.4 * f, Eigen::Vector3d::UnitZ())));
  return c;
}

/// `count` keyframes of `type` at frames 0..frames-1; on the horizon only when `flat` (the
/// polynomial then has no y term, which the turned solve must add).
EffectTrack spread_keyframes(EffectType type, int count, int frames, bool flat, Anchor anchor) {
  EffectTrack t;
  t.type = type;
  t.anchor = std::move(anchor);
  const int dim = effect_spec(type).dimension();
  for (int k = 0; k < count; ++k) {
    const Direction d{wrap_azimuth_deg(137.0 * k), flat ? 0.0 : 80.0 * std::sin(1.3 * k)};
    std::vector<double> v;
    for (int i = 0; i < dim; ++i) v.push_back(0.5 + 0.4 * std::sin(2.1 * k + i));
    t.keyframes.push_back({d, (k * 7) % frames, v});
  }
  return t;
}

TEST(StackAtFrame, EvaluatesAsTheStackAtItsFrameWithTheCentresTurnedOnce) {
  constexpr int kClip = 400;
  const CameraMotion camera = tumbling_camera(kClip);
  SubjectTrack actor{"actor", {}};
  for (int f = 0; f < kClip; ++f)
    actor.points.push_back(
        {f, {wrap_azimuth_deg(-170.0 + 3.0 * f), 40.0 * std::sin(0.05 * f)}, 1.0});
  const std::vector<SubjectTrack> tracks{actor};
  EffectTrack local = spread_keyframes(EffectType::Saturation, 300, kClip, false, kWorld);
  local.interpolation = InterpolationSettings{};
  local.interpolation->reach_s = 1.5;  // windows of a few seconds at 30 fps: blended
  const StackInterpolator stack(
      {spread_keyframes(EffectType::Exposure, 12, kClip, true, kWorld),
       spread_keyframes(EffectType::Tint, 9, kClip, false, {Anchor::Kind::Track, "actor"}),
       spread_keyframes(EffectType::Contrast, 5, kClip, false, {}), local},
      {}, 30.0, {&camera, tracks});
  ASSERT_TRUE(stack.interpolator(EffectType::Saturation)->local());
  ASSERT_FALSE(stack.interpolator(EffectType::Exposure)->basis().has(PolynomialBasis::Y));
  StackInterpolator::Solutions exposure_only{};
  exposure_only[static_cast<std::size_t>(EffectType::Exposure)] =
      stack.solution(EffectType::Exposure);
  const StackInterpolator unanchored(exposure_only);  // the same solve, no anchor
  double worst = 0.0, moved = 0.0;
  for (const std::int64_t f : {0, 1, 57, 199, 250, 399, 450}) {
    const StackAtFrame at(stack, f);
    EXPECT_EQ(at.frame(), f);
    for (double az = -175.0; az < 180.0; az += 25.0)
      for (double alt = -85.0; alt < 90.0; alt += 34.0) {
        const Direction d{az, alt};
        const StackParams want = stack.evaluate(d, f), got = at.evaluate(d);
        const StackParams unturned = unanchored.evaluate(d, f);
        for (const double e :
             {got.exposure_stops - want.exposure_stops, got.tint_gain[0] - want.tint_gain[0],
              got.tint_gain[2] - want.tint_gain[2], got.contrast - want.contrast,
              got.saturation - want.saturation})
          worst = std::max(worst, std::abs(e));
        moved = std::max(moved, std::abs(unturned.exposure_stops - want.exposure_stops));
      }
  }
  EXPECT_LT(worst, 1e-11);
  EXPECT_GT(moved, 0.1);  // the anchors do turn the field: the comparison is not vacuous
}

TEST(AnchoredFlares, IntensityAtTheTurnedGazeAndAFixedLightStaysInItsAnchorsFrame) {
  const CameraMotion camera = turning_camera();
  FlareEffect f;
  f.style = FlareStyle::Directional;
  f.settings = default_flare_settings(f.style);
  f.light = kWindow;  // the window's light, in the world
  f.anchor = kWorld;
  f.keyframes = {{kWindow, 0, {2.0}}, {kBehind, 0, {0.0}}};
  FlareEffect tracked = f;  // a light found in the video at each frame ignores the anchor
  tracked.light = std::vector<LightSample>{{0, {10.0, 0.0}}, {7, {80.0, 0.0}}};
  FlareEffect video_tracked = tracked;
  video_tracked.anchor = {};
  const FlareSet set({f, tracked}, {}, 30.0, {&camera, {}});
  const FlareSet fixed({video_tracked}, {}, 30.0);
  for (int frame = 0; frame < kFrames; ++frame) {
    const Direction at = video_of_world(kWindow, frame);
    EXPECT_NEAR(set.intensity(0, to_unit(at), frame), 2.0, 1e-9) << frame;
    EXPECT_LT(angle_deg(*set.light(0, frame), to_unit(at)), 1e-9) << frame;
    EXPECT_LT(angle_deg(*set.light(1, frame), *fixed.light(0, frame)), 1e-12) << frame;
    // Looking at the window, the flare is drawn from the window's light at full intensity.
    const auto layouts = set.layouts(looking_at(at), frame);
    ASSERT_FALSE(layouts.empty()) << frame;
    EXPECT_NEAR(layouts[0].intensity, 2.0, 1e-9);
  }
  // Replacing the intensity's solution (the editor's pending edit) keeps the anchor.
  FlareSet edited = set;
  edited.set_intensity(0, std::make_shared<const RbfInterpolator>(
                              std::vector<Keyframe>{{kWindow, 0, {3.0}}, {kBehind, 0, {0.0}}}, 1,
                              InterpolationSettings{}, 30.0, std::vector<double>{0.0}));
  EXPECT_NEAR(edited.intensity(0, to_unit(video_of_world(kWindow, 5)), 5), 3.0, 1e-9);
  EXPECT_THROW(FlareSet({f}, {}, 30.0), std::invalid_argument);
}

TEST(AnchoredGrain, ParametersAtTheTurnedForwardDirection) {
  const CameraMotion camera = turning_camera();
  GrainEffect g;
  g.style = GrainStyle::Headset;
  g.anchor = kWorld;
  g.keyframes = {{kWindow, 0, {0.8, 2.0}}, {kBehind, 0, {0.0, 1.0}}};
  GrainSet set({g}, {}, 30.0, {&camera, {}});
  for (int frame = 0; frame < kFrames; ++frame) {
    const Direction at = video_of_world(kWindow, frame);
    const GrainParams p = set.params(0, to_unit(at), frame);
    EXPECT_NEAR(p.intensity, 0.8, 1e-9) << frame;
    EXPECT_NEAR(p.size, 2.0, 1e-9) << frame;
    const auto layers = set.layout(looking_at(at), 0, frame);
    ASSERT_EQ(layers.size(), 1u) << frame;
    EXPECT_NEAR(layers[0].params.intensity, 0.8, 1e-9);
    // Behind the window, in the world: no grain, whichever way the camera points.
    EXPECT_NEAR(set.params(0, to_unit(video_of_world(kBehind, frame)), frame).intensity, 0.0, 1e-9);
  }
  EXPECT_THROW(GrainSet({g}, {}, 30.0), std::invalid_argument);
}

TEST(AnchorResolver, ResolvesEachAnchorOnceAndTheVideoAnchorToTheIdentity) {
  const CameraMotion camera = turning_camera();
  AnchorResolver resolve({&camera, {}});
  const ResolvedAnchor a = resolve.resolve(kWorld), b = resolve.resolve(kWorld);
  EXPECT_EQ(a.anchor, kWorld);
  EXPECT_FALSE(a.frames.identity());
  EXPECT_TRUE(resolve.resolve({}).frames.identity());
  for (int f = 0; f < kFrames; ++f) EXPECT_TRUE(a.frames.at(f) == b.frames.at(f));
  EXPECT_THROW(resolve.resolve({Anchor::Kind::Track, "nobody"}), std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
