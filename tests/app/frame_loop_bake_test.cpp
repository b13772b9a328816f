/// @file
/// @brief Per-pixel mode's baked parameter grid and its per-pixel application.
#include <gtest/gtest.h>

#include <cmath>

#include "app/frame_loop_bake.h"
#include "effects/effect_shaders.h"
#include "effects/effect_stack.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using effects::shader_bit;

TEST(FrameLoopBake, GridCellsSampleTheirCentres) {
  const ParamGrid g = bake_param_grid(
      [](const effects::Direction& d) {
        effects::StackParams p;
        p.exposure_stops = d.azimuth_deg / 100.0;
        p.contrast = 1.0 + d.altitude_deg / 100.0;
        return p;
      },
      8, 4);
  ASSERT_EQ(g.cells.size(), 32u);
  // Column i centre: azimuth (i + 0.5) / 8 * 360 - 180; row j centre: altitude 90 - (j + 0.5) 45.
  EXPECT_NEAR(g.at(0, 0).exposure_stops, -1.575, 1e-12);
  EXPECT_NEAR(g.at(7, 0).exposure_stops, 1.575, 1e-12);
  EXPECT_NEAR(g.at(0, 0).contrast, 1.675, 1e-12);
  EXPECT_NEAR(g.at(0, 3).contrast, 0.325, 1e-12);
}

TEST(FrameLoopBake, ConstantGridEqualsTheStackFormulas) {
  effects::StackParams p;
  p.tint_gain = effects::normalize_tint({1.5, 1.0, 0.5});
  p.exposure_stops = 0.7;
  p.saturation = 1.6;
  p.contrast = 0.8;
  const ParamGrid g = bake_param_grid([&](const effects::Direction&) { return p; }, 16, 8);
  cv::Mat rgb(32, 64, CV_32FC3);
  cv::randu(rgb, 0.0f, 1.0f);
  const cv::Mat out = apply_param_grid(rgb, g, baked_effects_mask());
  for (int y = 0; y < rgb.rows; y += 7)
    for (int x = 0; x < rgb.cols; x += 5) {
      const cv::Vec3f c = rgb.at<cv::Vec3f>(y, x);
      const Eigen::Vector3d want =
          effects::apply_colour_stack(Eigen::Vector3d(c[0], c[1], c[2]), p, 0.0);
      const cv::Vec3f got = out.at<cv::Vec3f>(y, x);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 2e-5) << x << "," << y;
    }
  // Effects outside the mask are not applied.
  const cv::Mat only_exposure = apply_param_grid(rgb, g, shader_bit(EffectType::Exposure));
  const cv::Vec3f c = rgb.at<cv::Vec3f>(3, 3);
  EXPECT_NEAR(only_exposure.at<cv::Vec3f>(3, 3)[1], c[1] * std::pow(2.0, 0.7), 2e-5);
}

TEST(FrameLoopBake, ParametersAreBilinearAndWrapAtTheSeam) {
  // Exposure grows linearly with azimuth except across the seam; a 4-column grid on a 64-pixel
  // frame puts pixel columns between cell centres.
  const ParamGrid g = bake_param_grid(
      [](const effects::Direction& d) {
        effects::StackParams p;
        p.exposure_stops = d.azimuth_deg > 0 ? 1.0 : 0.0;
        return p;
      },
      4, 2);
  cv::Mat grey(2, 64, CV_32FC3, cv::Scalar(0.25, 0.25, 0.25));
  const cv::Mat out = apply_param_grid(grey, g, shader_bit(EffectType::Exposure));
  const auto stops = [&](int x) { return std::log2(out.at<cv::Vec3f>(0, x)[0] / 0.25); };
  // Cell centres at pixel-centre coordinates 8, 24, 40, 56 (0, 0, 1, 1 stops); the columns left
  // of 8 and right of 56 interpolate towards the other side of the seam.
  const struct {
    int x;
    double stops;
  } rows[] = {{15, 0.0}, {7, 1.0 / 32}, {31, 15.0 / 32}, {55, 1.0}, {0, 15.0 / 32}, {63, 17.0 / 32}};
  for (const auto& r : rows) EXPECT_NEAR(stops(r.x), r.stops, 1e-5) << r.x;
}

}  // namespace
}  // namespace vdfx::app
