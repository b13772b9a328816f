/// @file
/// @brief `auto` light: a bright disc moving over a synthetic equirect is tracked within 1 degree;
/// a frame without a bright region gives none; the result depends on the frames only (not on
/// the order they were seen); the brighter of two lights wins without being pulled to the other.
#include "effects/auto_light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "effects/coords.h"

namespace vdfx::effects {
namespace {

/// A daylight-like equirect (RGB float): sky brightening towards the horizon, darker textured
/// ground, and optional discs (centre, angular radius, level) with a soft 0.5-degree edge.
struct Disc {
  Direction centre;
  double radius_deg;
  double level;
};

cv::Mat synthetic_sky(int w, const std::vector<Disc>& discs) {
  const int h = w / 2;
  cv::Mat img(h, w, CV_32FC3);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const Direction d = from_equirect_uv({(i + 0.5) / w, (j + 0.5) / h});
      double v = d.altitude_deg > 0 ? 0.55 - 0.3 * d.altitude_deg / 90.0
                                    : 0.25 + 0.08 * std::sin(0.3 * i) * std::cos(0.2 * j);
      cv::Vec3f c(static_cast<float>(0.8 * v), static_cast<float>(0.9 * v),
                  static_cast<float>(1.1 * v));
      for (const Disc& disc : discs) {
        const double a = angle_between(to_unit(d), to_unit(disc.centre)) * kRadToDeg;
        const double t = std::clamp((disc.radius_deg + 0.25 - a) / 0.5, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) c[k] = static_cast<float>((1 - t) * c[k] + t * disc.level);
      }
      img.at<cv::Vec3f>(j, i) = c;
    }
  }
  return img;
}

Direction sun_path(int frame) {
  // Across the frame, over the seam, rising and setting: about 5 degrees per frame.
  return {wrap_azimuth_deg(120.0 + 5.0 * frame), 8.0 + 25.0 * std::sin(frame * 0.08)};
}

double deg_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return angle_between(a, b) * kRadToDeg;
}

TEST(AutoLight, TracksADiscMovingAcrossTheFrameWithinOneDegree) {
  AutoLightTracker tracker;
  double worst = 0.0;
  for (int f = 0; f < 30; ++f) {
    tracker.observe(f, synthetic_sky(1024, {{sun_path(f), 3.0, 1.0}}));
    const auto light = tracker.light(f);
    ASSERT_TRUE(light) << "frame " << f;
    const double err = deg_between(*light, to_unit(sun_path(f)));
    worst = std::max(worst, err);
    EXPECT_LT(err, 1.0) << "frame " << f;
  }
  std::cout << "auto light: worst error " << worst << " deg over 30 frames\n";
}

TEST(AutoLight, NoLightWithoutABrightRegion) {
  EXPECT_FALSE(find_brightest_region(synthetic_sky(512, {})));
  // A uniformly bright frame (overcast, or a white wall) has no sun either.
  EXPECT_FALSE(find_brightest_region(cv::Mat(256, 512, CV_32FC3, cv::Scalar::all(0.95))));
  EXPECT_FALSE(find_brightest_region(cv::Mat(256, 512, CV_32FC3, cv::Scalar::all(0.0))));
  EXPECT_FALSE(find_brightest_region(cv::Mat()));
  AutoLightTracker tracker;
  tracker.observe(3, synthetic_sky(512, {}));
  EXPECT_TRUE(tracker.observed(3));
  EXPECT_FALSE(tracker.light(3));
  EXPECT_FALSE(tracker.light(4));  // never observed
  // The same sky with a sun has one, in float and in 8-bit frames alike.
  const cv::Mat sunny = synthetic_sky(512, {{{0.0, 20.0}, 3.0, 1.0}});
  const auto from_float = find_brightest_region(sunny);
  ASSERT_TRUE(from_float);
  cv::Mat bytes;
  sunny.convertTo(bytes, CV_8UC3, 255.0);
  const auto from_bytes = find_brightest_region(bytes);
  ASSERT_TRUE(from_bytes);
  EXPECT_LT(angle_between(*from_float, *from_bytes) * kRadToDeg, 0.1);
}

TEST(AutoLight, TheBrighterOfTwoLightsWinsUnpulledByTheOther) {
  const Direction sun{-50.0, 30.0}, lamp{60.0, 10.0};
  const auto light =
      find_brightest_region(synthetic_sky(1024, {{sun, 2.5, 4.0}, {lamp, 2.5, 1.0}}));
  ASSERT_TRUE(light);
  EXPECT_LT(deg_between(*light, to_unit(sun)), 0.5);
}

TEST(AutoLight, AClippedPlateauPeaksInItsMiddle) {
  // An LDR frame whose sun is a wide region clipped at 1.0: the light is its centre.
  const Direction sun{30.0, 40.0};
  const auto light = find_brightest_region(synthetic_sky(1024, {{sun, 9.0, 1.0}}));
  ASSERT_TRUE(light);
  EXPECT_LT(deg_between(*light, to_unit(sun)), 1.0);
}

TEST(AutoLight, ResultDependsOnTheFramesNotOnTheOrderTheyWereSeen) {
  std::vector<cv::Mat> frames;
  for (int f = 0; f < 8; ++f) frames.push_back(synthetic_sky(512, {{sun_path(f), 3.0, 1.0}}));
  AutoLightTracker forward, backward;
  for (int f = 0; f < 8; ++f) forward.observe(f, frames[static_cast<std::size_t>(f)]);
  for (int f = 7; f >= 0; --f) backward.observe(f, frames[static_cast<std::size_t>(f)]);
  for (int f = 0; f < 8; ++f) EXPECT_EQ(*forward.light(f), *backward.light(f)) << f;
  // A lone frame rendered with its window observed gives the playback's answer.
  AutoLightTracker lone;
  for (int f = 7 - lone.window(); f <= 7; ++f) lone.observe(f, frames[static_cast<std::size_t>(f)]);
  EXPECT_EQ(*lone.light(7), *forward.light(7));
}

TEST(AutoLight, SmoothingAveragesJitterAndAJumpRestartsTheFit) {
  // A still sun measured with jitter (alternating offsets): the fit lands nearer the truth than
  // the raw measurement of the frame.
  const Direction sun{10.0, 20.0};
  AutoLightTracker tracker;
  for (int f = 0; f < 5; ++f) {
    const double jitter = (f % 2 ? 0.6 : -0.6);
    tracker.observe(
        f, synthetic_sky(1024, {{{sun.azimuth_deg + jitter, sun.altitude_deg}, 3.0, 1.0}}));
  }
  const double raw = deg_between(
      *find_brightest_region(synthetic_sky(1024, {{{9.4, 20.0}, 3.0, 1.0}})), to_unit(sun));
  const double fitted = deg_between(*tracker.light(4), to_unit(sun));
  std::cout << "jitter +-0.6 deg: raw " << raw << " deg, fitted " << fitted << " deg\n";
  EXPECT_LT(fitted, 0.5 * raw);
  // A cut to a sun 60 degrees away: the new position at once, not a blend with the old.
  tracker.observe(5, synthetic_sky(1024, {{{70.0, 20.0}, 3.0, 1.0}}));
  EXPECT_LT(deg_between(*tracker.light(5), to_unit({70.0, 20.0})), 0.5);
}

}  // namespace
}  // namespace vdfx::effects
