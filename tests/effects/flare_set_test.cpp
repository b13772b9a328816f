/// @file
/// @brief FlareSet: intensity keyframes through the RBF, light sources (fixed, track, auto),
/// several flares at once, and no flare without intensity or without a light.
#include "effects/flare_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "effects/auto_light.h"
#include "effects/flare_set_cv.h"
#include "effects/view_camera.h"

namespace vdfx::effects {
namespace {

HeadPose looking_at(const Direction& d) {
  HeadPose h;
  h.orientation = pose_rotation({d, 0.0});
  return h;
}

FlareEffect flare(FlareLight light, std::vector<Keyframe> keyframes) {
  FlareEffect f;
  f.light = std::move(light);
  f.settings = default_flare_settings(f.style);
  f.keyframes = std::move(keyframes);
  return f;
}

TEST(FlareSet, IntensityIsTheKeyframesRbfAtTheGazeClampedToItsRange) {
  // Strong when looking left of the light, none when looking right of it.
  const std::vector<Keyframe> kfs{{{-10.0, 0.0}, 0, {3.0}}, {{10.0, 0.0}, 0, {0.0}}};
  const FlareSet set({flare(Direction{0.0, 0.0}, kfs)}, {}, 30.0);
  EXPECT_NEAR(set.intensity(0, to_unit({-10.0, 0.0}), 0), 3.0, 1e-9);
  EXPECT_NEAR(set.intensity(0, to_unit({10.0, 0.0}), 0), 0.0, 1e-9);
  const double mid = set.intensity(0, to_unit({0.0, 0.0}), 0);
  EXPECT_GT(mid, 0.0);
  EXPECT_LT(mid, 3.0);
  EXPECT_EQ(set.layouts(looking_at({10.0, 0.0}), 0).size(), 0u);
  const auto left = set.layouts(looking_at({-10.0, 0.0}), 0);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_NEAR(left[0].intensity, 3.0, 1e-9);
  // Where the RBF itself overshoots the range, the intensity is clamped to 0..4.
  const std::vector<Keyframe> steep_kfs{
      {{-1.0, 0.0}, 0, {4.0}}, {{1.0, 0.0}, 0, {0.0}}, {{0.0, 30.0}, 0, {2.0}}};
  const InterpolationSettings smooth{1.5, 1.0};  // overshoots between keyframes 0 and 4
  const FlareSet steep({flare(Direction{0.0, 0.0}, steep_kfs)}, smooth, 30.0);
  const RbfInterpolator raw(steep_kfs, 1, smooth, 30.0, {0.0});
  double lo = 1e9, hi = -1e9;
  for (double az = -180.0; az < 180.0; az += 5.0) {
    for (double alt = -80.0; alt <= 80.0; alt += 10.0) {
      const Eigen::Vector3d n = to_unit({az, alt});
      const double r = raw.evaluate(n, 0)[0], v = steep.intensity(0, n, 0);
      lo = std::min(lo, r), hi = std::max(hi, r);
      EXPECT_EQ(v, std::clamp(r, 0.0, 4.0));
    }
  }
  EXPECT_LT(lo, 0.0);  // the clamp was needed on both sides
  EXPECT_GT(hi, 4.0);
}

TEST(FlareSet, NoKeyframesMeansNeutralIntensityAndNoFlare) {
  const FlareSet set({flare(Direction{0.0, 0.0}, {})}, {}, 30.0);
  EXPECT_EQ(set.intensity(0, to_unit({0.0, 0.0}), 0), 0.0);
  EXPECT_TRUE(set.layouts(looking_at({0.0, 0.0}), 0).empty());
}

TEST(FlareSet, TrackAndAutoLightsAndSeveralFlares) {
  const std::vector<Keyframe> on{{{0.0, 0.0}, 0, {1.0}}};
  std::vector<FlareEffect> flares{
      flare(std::vector<LightSample>{{0, {-20.0, 0.0}}, {10, {20.0, 0.0}}}, on),
      flare(AutoLight{}, on),
  };
  const FlareSet set(flares, {}, 30.0);
  EXPECT_TRUE(set.uses_auto_light());
  EXPECT_LT(angle_between(*set.light(0, 5), to_unit({0.0, 0.0})), 1e-12);
  EXPECT_FALSE(set.light(1, 5));  // no frame seen yet: no auto light
  ASSERT_EQ(set.layouts(looking_at({0.0, 0.0}), 5).size(), 1u);

  // A frame with a bright spot at (3, 2): both flares now.
  FlareSet seen(flares, {}, 30.0);
  cv::Mat frame(256, 512, CV_32FC3, cv::Scalar::all(0.2));
  const Eigen::Vector2d uv = to_equirect_uv({3.0, 2.0});
  cv::circle(frame, cv::Point(static_cast<int>(uv.x() * 512), static_cast<int>(uv.y() * 256)), 4,
             cv::Scalar::all(1.0), cv::FILLED);
  observe_frame(seen, 5, frame);
  ASSERT_TRUE(seen.light(1, 5));
  EXPECT_LT(angle_between(*seen.light(1, 5), to_unit({3.0, 2.0})) * kRadToDeg, 1.0);
  EXPECT_EQ(seen.layouts(looking_at({0.0, 0.0}), 5).size(), 2u);
}

// The web player's way (no OpenCV): the lights publish tracked, handed over whole, replace the
// tracker: frame f's entry, none for a null entry or beyond the list.
TEST(FlareSet, GivenAutoLightsReplaceTheTracker) {
  const std::vector<Keyframe> on{{{0.0, 0.0}, 0, {1.0}}};
  FlareSet set({flare(AutoLight{}, on)}, {}, 30.0);
  const Eigen::Vector3d a = to_unit({10.0, 5.0}), b = to_unit({12.0, 5.0});
  set.set_auto_lights({a, std::nullopt, b});
  EXPECT_LT(angle_between(*set.light(0, 0), a), 1e-15);
  EXPECT_FALSE(set.light(0, 1));
  EXPECT_LT(angle_between(*set.light(0, 2), b), 1e-15);
  EXPECT_FALSE(set.light(0, 3));
  EXPECT_FALSE(set.light(0, -1));
  EXPECT_EQ(set.layouts(looking_at({10.0, 5.0}), 0).size(), 1u);
  EXPECT_TRUE(set.layouts(looking_at({10.0, 5.0}), 1).empty());
}

// A measurement recorded by hand is what observe_frame records for the frame it measures.
TEST(FlareSet, RecordedMeasurementsTrackAsObservedFrames) {
  const std::vector<Keyframe> on{{{0.0, 0.0}, 0, {1.0}}};
  FlareSet observed({flare(AutoLight{}, on)}, {}, 30.0), recorded = observed;
  for (int f = 0; f < 4; ++f) {
    cv::Mat frame(128, 256, CV_32FC3, cv::Scalar::all(0.2));
    const Eigen::Vector2d uv = to_equirect_uv({20.0 + 2.0 * f, 10.0});
    cv::circle(frame, cv::Point(static_cast<int>(uv.x() * 256), static_cast<int>(uv.y() * 128)), 3,
               cv::Scalar::all(1.0), cv::FILLED);
    observe_frame(observed, f, frame);
    recorded.record_light(f, find_brightest_region(frame, recorded.auto_light_options()));
  }
  for (int f = 0; f < 4; ++f) {
    ASSERT_TRUE(observed.light(0, f));
    EXPECT_EQ(*observed.light(0, f), *recorded.light(0, f)) << "frame " << f;
  }
}

}  // namespace
}  // namespace vdfx::effects
