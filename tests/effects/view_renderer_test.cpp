/// @file
/// @brief View renderer: view vs pixel mode, centre direction, clamping at the end, 8-bit output,
/// and consistency on a real equirect image.
#include "effects/view_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "effects/effect_stack.h"

namespace vdfx::effects {
namespace {

const char* const kSunrise = "/usr/share/blender/datafiles/studiolights/world/sunrise.exr";

/// A real CC0 equirect (blender-data), RGB float as the renderer expects.
cv::Mat load_sunrise() {
  setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1);
  cv::Mat bgr = cv::imread(kSunrise, cv::IMREAD_UNCHANGED);
  if (bgr.empty()) return {};
  if (bgr.channels() == 4) cv::cvtColor(bgr, bgr, cv::COLOR_BGRA2BGR);
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  rgb.convertTo(rgb, CV_32FC3);
  return rgb;
}

cv::Mat grey(double level) {
  return cv::Mat(32, 64, CV_32FC3, cv::Scalar::all(level));
}

/// Exposure that grows with azimuth: one stop per 45 degrees.
StackParams exposure_by_azimuth(const Direction& d) {
  StackParams p;
  p.exposure_stops = d.azimuth_deg / 45.0;
  return p;
}

TEST(ViewRenderer, ViewModeHasNoGradientPixelModeDoes) {
  const cv::Mat img = grey(0.25);
  const EquirectSampler sampler(img, {SampleFilter::Bilinear, PoleRows::Clamp});
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{20, 0}, 0}, 90.0, 41, 21);
  const cv::Mat view = render_view(sampler, cam, exposure_by_azimuth, RenderMode::View);
  const cv::Mat pixel = render_view(sampler, cam, exposure_by_azimuth, RenderMode::Pixel);
  double lo, hi;
  cv::minMaxLoc(view.reshape(1), &lo, &hi);
  EXPECT_EQ(lo, hi);
  EXPECT_NEAR(hi, 0.25 * std::exp2(20.0 / 45.0), 1e-6);  // evaluated at the centre
  // Pixel mode: each pixel carries its own exposure, increasing to the right.
  for (int i = 0; i < cam.width(); ++i) {
    const double az = from_unit(cam.pixel_ray(i, 10)).azimuth_deg;
    EXPECT_NEAR(pixel.at<cv::Vec3f>(10, i)[1], 0.25 * std::exp2(az / 45.0), 1e-6) << i;
    if (i > 0) {
      EXPECT_GT(pixel.at<cv::Vec3f>(10, i)[1], pixel.at<cv::Vec3f>(10, i - 1)[1]);
    }
  }
}

TEST(ViewRenderer, ViewModeEvaluatesAtTheCentreDirection) {
  const EquirectSampler sampler(grey(0.5), {SampleFilter::Bilinear, PoleRows::Clamp});
  // Asymmetric eye with roll: the centre direction is the optical axis, the look direction.
  const ViewCamera cam =
      ViewCamera::from_fov_angles({{-130, 35}, 25}, {-0.9, 0.5, 0.7, -0.6}, 30, 20);
  int calls = 0;
  Direction seen;
  const ParamsAt record = [&](const Direction& d) {
    ++calls;
    seen = d;
    return StackParams{};
  };
  render_view(sampler, cam, record, RenderMode::View);
  EXPECT_EQ(calls, 1);
  EXPECT_NEAR(seen.azimuth_deg, -130.0, 1e-9);
  EXPECT_NEAR(seen.altitude_deg, 35.0, 1e-9);
  calls = 0;
  render_view(sampler, cam, record, RenderMode::Pixel);
  EXPECT_EQ(calls, 30 * 20);
}

TEST(ViewRenderer, ClampsOnlyAtTheEnd) {
  // 0.8 * 2 = 1.6, then contrast 0.25: 0.5 + 0.25 * 1.1 = 0.775 (clamping between effects would
  // give 0.625).
  const EquirectSampler sampler(grey(0.8), {SampleFilter::Bilinear, PoleRows::Clamp});
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 0}, 0}, 60.0, 8, 8);
  StackParams p;
  p.exposure_stops = 1.0;
  p.contrast = 0.25;
  const cv::Mat out = render_view(sampler, cam, p);
  EXPECT_NEAR(out.at<cv::Vec3f>(3, 3)[0], 0.775, 1e-6);
  // And the float result stays unclamped: exposure alone leaves 1.6.
  StackParams bright;
  bright.exposure_stops = 1.0;
  const cv::Mat over = render_view(sampler, cam, bright);
  EXPECT_NEAR(over.at<cv::Vec3f>(0, 0)[2], 1.6, 1e-6);
  EXPECT_EQ(to_rgb8(over).at<cv::Vec3b>(0, 0), cv::Vec3b(255, 255, 255));
}

TEST(ViewRenderer, EightBitOutputClampsScalesRounds) {
  const struct {
    float in;
    unsigned char out;
  } rows[] = {{-0.5f, 0},  {0.0f, 0},   {0.2f, 51},         {0.5f, 128},        {0.999f, 255},
              {1.0f, 255}, {1.7f, 255}, {std::nanf(""), 0}, {1.0f / 255.0f, 1}, {0.4f / 255.0f, 0}};
  for (const auto& r : rows) {
    const cv::Mat px(1, 1, CV_32FC3, cv::Scalar(r.in, 0.0, 1.0));
    const cv::Vec3b got = to_rgb8(px).at<cv::Vec3b>(0, 0);
    EXPECT_EQ(got[0], r.out) << r.in;
    EXPECT_EQ(got[1], 0);  // channel order is kept (RGB in, RGB out)
    EXPECT_EQ(got[2], 255);
  }
}

TEST(ViewRenderer, BlurredViewHasNoBorderEffect) {
  // A uniform sphere stays uniform under blur because the view is rendered with a margin; a
  // border that repeated or dropped pixels would still be uniform, so use a vertical ramp in
  // altitude seen sideways: with a margin the edge rows keep the linear profile.
  cv::Mat ramp(90, 180, CV_32FC3);
  for (int y = 0; y < 90; ++y) ramp.row(y).setTo(cv::Scalar::all(y / 89.0));
  const EquirectSampler sampler(ramp, {SampleFilter::Bilinear, PoleRows::Clamp});
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 0}, 0}, 20.0, 40, 40);
  StackParams p;
  p.blur_sigma_deg = 1.0;
  const cv::Mat sharp = sample_view(sampler, cam);
  const cv::Mat blurred = render_view(sampler, cam, p);
  // A linear profile is unchanged by a symmetric kernel, including at the top and bottom rows.
  EXPECT_NEAR(blurred.at<cv::Vec3f>(0, 20)[0], sharp.at<cv::Vec3f>(0, 20)[0], 2e-4);
  EXPECT_NEAR(blurred.at<cv::Vec3f>(39, 20)[0], sharp.at<cv::Vec3f>(39, 20)[0], 2e-4);
  // With the image's own border repeated (apply_stack) the edge row is pulled inwards.
  const cv::Mat bordered = apply_stack(sharp, p, cam);
  EXPECT_GT(std::abs(bordered.at<cv::Vec3f>(0, 20)[0] - sharp.at<cv::Vec3f>(0, 20)[0]), 1e-3);
}

TEST(ViewRenderer, RealImageModesAgreeForConstantParameters) {
  const cv::Mat img = load_sunrise();
  ASSERT_FALSE(img.empty()) << "cannot read " << kSunrise;
  const EquirectSampler sampler(img);
  const ViewCamera cameras[] = {
      ViewCamera::from_horizontal_fov({{35, 10}, 0}, 90.0, 64, 48),
      ViewCamera::from_fov_angles({{-170, 75}, 20}, {-0.9, 0.5, 0.7, -0.6}, 48, 48),  // pole
  };
  StackParams p;
  p.set(EffectType::Tint, std::vector<double>{1.2, 1.0, 0.7});
  p.exposure_stops = -0.5;
  p.saturation = 1.4;
  p.contrast = 1.2;
  p.vignette_radius_deg = 25;
  p.vignette_falloff_deg = 15;
  for (const auto& cam : cameras) {
    // Neutral parameters give exactly the sampled view.
    EXPECT_EQ(
        cv::norm(render_view(sampler, cam, StackParams{}), sample_view(sampler, cam), cv::NORM_INF),
        0.0);
    for (double sigma : {0.0, 1.5}) {
      p.blur_sigma_deg = sigma;
      const cv::Mat view = render_view(sampler, cam, p);
      const cv::Mat pixel = render_view(
          sampler, cam, [&](const Direction&) { return p; }, RenderMode::Pixel);
      EXPECT_TRUE(cv::checkRange(view));
      EXPECT_LT(cv::norm(view, pixel, cv::NORM_INF), 1e-4) << "sigma " << sigma;
      EXPECT_GT(cv::norm(view, sample_view(sampler, cam), cv::NORM_INF), 0.01);
    }
  }
}

TEST(ViewRenderer, PixelModeBlurVariesAcrossTheView) {
  // Blur growing with azimuth: a fine checkerboard keeps its contrast on the left and loses it on
  // the right.
  cv::Mat checker(180, 360, CV_32FC3);
  for (int y = 0; y < 180; ++y)
    for (int x = 0; x < 360; ++x)
      checker.at<cv::Vec3f>(y, x) = cv::Vec3f::all(((x / 2 + y / 2) % 2));
  const EquirectSampler sampler(checker, {SampleFilter::Bilinear, PoleRows::Clamp});
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 0}, 0}, 60.0, 60, 20);
  const auto blur_right = [](const Direction& d) {
    StackParams p;
    p.blur_sigma_deg = d.azimuth_deg > 0.0 ? 2.0 : 0.0;
    return p;
  };
  const cv::Mat out = render_view(sampler, cam, blur_right, RenderMode::Pixel);
  cv::Scalar m, left_dev, right_dev;
  cv::meanStdDev(out(cv::Rect(0, 0, 25, 20)).clone().reshape(1), m, left_dev);
  cv::meanStdDev(out(cv::Rect(35, 0, 25, 20)).clone().reshape(1), m, right_dev);
  EXPECT_GT(left_dev[0], 0.3);
  EXPECT_LT(right_dev[0], 0.05);
}

}  // namespace
}  // namespace vdfx::effects
