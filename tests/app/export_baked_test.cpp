/// @file
/// @brief The baked export's frame render: per-pixel colour formulas against the CPU reference,
/// parameters at each pixel's own direction, the grid step's error, the vignette left out.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <thread>

#include "app/export/baked_export.h"
#include "effects/coords.h"
#include "effects/effect_stack.h"
#include "effects/stack_interpolator.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

effects::EffectTrack track(EffectType t,
                           std::vector<std::pair<effects::Direction, std::vector<double>>> kfs) {
  effects::EffectTrack tr;
  tr.type = t;
  for (auto& [d, v] : kfs) tr.keyframes.push_back({d, 0, v});
  return tr;
}

effects::StackInterpolator stack_of(std::vector<effects::EffectTrack> tracks) {
  return effects::StackInterpolator(tracks, effects::InterpolationSettings{}, 30.0);
}

TEST(ExportBaked, ColourPixelIsTheReferencesFormulas) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ColourMask all{true, true, true};
  for (int i = 0; i < 2000; ++i) {
    effects::StackParams p;
    const Eigen::Vector3d tint(0.2 + 2 * unit(rng), 0.2 + 2 * unit(rng), 0.2 + 2 * unit(rng));
    p.tint_gain = tint / (0.25 * tint.x() + 0.5 * tint.y() + 0.25 * tint.z());
    p.exposure_stops = -3 + 6 * unit(rng);
    p.saturation = 2 * unit(rng);
    p.contrast = 2 * unit(rng);
    const double e = std::exp2(p.exposure_stops);
    const float f[5] = {static_cast<float>(p.tint_gain.x() * e),
                        static_cast<float>(p.tint_gain.y() * e),
                        static_cast<float>(p.tint_gain.z() * e), static_cast<float>(p.saturation),
                        static_cast<float>(p.contrast)};
    const Eigen::Vector3d c(unit(rng), unit(rng), unit(rng));
    const Eigen::Vector3d want = effects::apply_colour_stack(c, p, 0.0);
    float got[3] = {static_cast<float>(c.x()), static_cast<float>(c.y()),
                    static_cast<float>(c.z())};
    apply_colour_pixel(got, f, all);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(got[k], want[k], 2e-5 * std::max(1.0, std::abs(want[k]))) << i;
  }
  // Effects the stack does not have leave the pixel exactly as it was.
  float c[3] = {0.3f, 0.6f, 0.9f};
  const float f[5] = {2, 1, 0.5, 0.1f, 3};
  apply_colour_pixel(c, f, ColourMask{});
  EXPECT_EQ(c[0], 0.3f);
  EXPECT_EQ(c[2], 0.9f);
}

TEST(ExportBaked, EveryPixelGetsTheParametersOfItsOwnDirection) {
  const auto stack = stack_of(
      {track(EffectType::Exposure, {{{0, 0}, {1.0}}, {{180, 0}, {-1.0}}, {{90, 60}, {0.5}}})});
  const int w = 64, h = 32;
  const cv::Mat grey(h, w, CV_32FC3, cv::Scalar::all(0.25));
  BakedOptions exact;
  exact.param_step = 1;
  const cv::Mat out = render_baked(grey, stack, 0, exact);
  double worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double az = ((x + 0.5) / w - 0.5) * 360.0, alt = (0.5 - (y + 0.5) / h) * 180.0;
      const double want =
          0.25 * std::exp2(stack.evaluate(effects::Direction{az, alt}, 0).exposure_stops);
      worst = std::max(worst, std::abs(out.at<cv::Vec3f>(y, x)[1] - want));
    }
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(out.at<cv::Vec3f>(h / 2, w / 2)[1], 0.5, 0.02);  // looking at azimuth 0: +1 stop
  EXPECT_NEAR(out.at<cv::Vec3f>(h / 2, 0)[1], 0.125, 0.01);    // behind: -1 stop
  // A coarser grid (every 2.8 degrees; the default for 3840-wide video is every 0.75): bilinear
  // between exact values, close to the exact field.
  const cv::Mat grey2(128, 256, CV_32FC3, cv::Scalar::all(0.25));
  BakedOptions coarse;
  coarse.param_step = 2;
  cv::Mat d;
  cv::absdiff(render_baked(grey2, stack, 0, coarse), render_baked(grey2, stack, 0, exact), d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  EXPECT_GT(mx, 0.0);
  EXPECT_LT(mx, 1.0 / 255.0);
  EXPECT_EQ(baked_param_step(BakedOptions{}, 3840), 8);
  EXPECT_EQ(baked_param_step(BakedOptions{}, 512), 1);
}

TEST(ExportBaked, TheVignetteIsLeftOut) {
  const auto stack = stack_of({track(EffectType::Vignette, {{{0, 0}, {20.0, 10.0}}})});
  EXPECT_TRUE(baked_drops_effects(stack));
  cv::Mat img(16, 32, CV_32FC3);
  cv::randu(img, 0.0, 1.0);
  cv::Mat d;
  cv::absdiff(render_baked(img, stack, 0), img, d);
  EXPECT_EQ(cv::countNonZero(d.reshape(1)), 0);
  EXPECT_FALSE(baked_drops_effects(stack_of({track(EffectType::Exposure, {{{0, 0}, {1.0}}})})));
}

}  // namespace
}  // namespace vdfx::app

namespace vdfx::app {
namespace {

/// Exposure keyframes at frames 10 and 20: held (the same field) before 10 and after 20.
effects::StackInterpolator timed_stack() {
  effects::EffectTrack tr;
  tr.type = effects::EffectType::Exposure;
  tr.keyframes = {
      {{0, 0}, 10, {1.0}}, {{180, 0}, 10, {-1.0}}, {{0, 0}, 20, {-1.0}}, {{180, 0}, 20, {1.0}}};
  return effects::StackInterpolator({tr}, effects::InterpolationSettings{}, 30.0);
}

TEST(ExportBaked, GridCacheReusesTheGridOnlyWhileTheEvaluatedFrameIsTheSame) {
  const auto stack = timed_stack();
  const cv::Mat grey(32, 64, CV_32FC3, cv::Scalar(0.25, 0.25, 0.25));
  BakedGridCache cache;
  BakedOptions cached;
  cached.cache = &cache;
  const auto same = [&](std::int64_t frame) {
    cv::Mat d;
    cv::absdiff(render_baked(grey, stack, frame, cached), render_baked(grey, stack, frame), d);
    double worst = 0.0;
    cv::minMaxLoc(d.reshape(1), nullptr, &worst);
    return worst;
  };
  // Frames 0..9 all evaluate at frame 10 (held): the cached grid of frame 0 serves frame 5.
  EXPECT_EQ(same(0), 0.0);
  const std::vector<std::int64_t> key_held{64, 32, 1, 360, 10};  // w, h, step, coverage, frame
  EXPECT_NE(cache.find(key_held), nullptr);
  EXPECT_EQ(same(5), 0.0);
  // Inside the span every frame has its own field; the cache must not hand out frame 5's.
  EXPECT_EQ(same(15), 0.0);
  EXPECT_EQ(cache.find(key_held), nullptr) << "frame 15 replaced the held grid";
  EXPECT_EQ(same(25), 0.0);  // held at 20
  // And the fields really differ (so the comparisons above could fail).
  cv::Mat a = render_baked(grey, stack, 0), b = render_baked(grey, stack, 25), d;
  cv::absdiff(a, b, d);
  double worst = 0.0;
  cv::minMaxLoc(d.reshape(1), nullptr, &worst);
  EXPECT_GT(worst, 0.2);
}

TEST(ExportBaked, GridCacheMakesAKeyOnceForThreadsAskingTogether) {
  // The render threads of an export start together and ask for the same grid: one makes it, the
  // other waits for that one instead of making its own.
  BakedGridCache cache;
  const std::vector<std::int64_t> key{1, 2, 3};
  std::atomic<int> made{0};
  std::atomic<bool> entered{false};
  const auto make = [&]() -> BakedGridCache::Grid {
    ++made;
    entered = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return std::make_shared<const BakedGrid>();
  };
  BakedGridCache::Grid first, second;
  std::thread a([&] { first = cache.get_or_make(key, make); });
  while (!entered) std::this_thread::yield();
  std::thread b([&] { second = cache.get_or_make(key, make); });
  a.join();
  b.join();
  EXPECT_EQ(made.load(), 1);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first, second);
  // Another key is made anew; a failing make leaves no thread waiting on its key.
  const std::vector<std::int64_t> other{4};
  EXPECT_THROW(
      cache.get_or_make(other, []() -> BakedGridCache::Grid { throw std::runtime_error("x"); }),
      std::runtime_error);
  EXPECT_NE(cache.get_or_make(other, make), nullptr);
  EXPECT_EQ(made.load(), 2);
}

}  // namespace
}  // namespace vdfx::app
