/// @file
/// @brief Per-pixel mode on the GPU (compositor with a parameter grid) against the CPU reference
/// per-pixel render (effects::render_view, RenderMode::Pixel, the same parameter function).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "effects/effect_shaders.h"
#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"
#include "gl_test_support.h"
#include "xr/render/compositor.h"
#include "xr/render/gpu_timer.h"

namespace vdfx::xr {
namespace {

using effects::Direction;
using effects::EffectType;
using effects::StackParams;
using test::GlTest;

class PerPixelGlTest : public GlTest {};

// 200 x 150 at 50 degrees: 4 px/degree, magnified everywhere, so the video layer and the CPU
// sampler both read level 0 (as in compositor_gl_test.cpp).
constexpr int kW = 200, kH = 150;
constexpr double kFov = 50.0;
const effects::ViewPose kPose{{-10, 5}, 10};

cv::Mat gpu_eye(const cv::Mat& eq_bgr, const effects::ParamsAt& at, unsigned mask, bool per_pixel,
                int grid_w, int grid_h, BlurMethod blur, double level_ratio = kHalfOctaveLevels,
                double* ms = nullptr) {
  CompositorConfig c;
  c.blur_level_ratio = level_ratio;
  c.eye_width = kW;
  c.eye_height = kH;
  c.eye_format = TexFormat::RGBA32F;
  c.distortion.method = DistortionMethod::None;
  c.blur = blur;
  Compositor comp(c);
  comp.set_video_frame(eq_bgr);
  const RenderView v = RenderView::look_at(kPose.look, kPose.roll_deg, kFov, kW, kH);
  EyeInput in{v, at(effects::from_unit(v.world_ray(kW / 2.0, kH / 2.0, kW, kH))), mask, per_pixel};
  if (per_pixel) comp.set_param_grid(bake_param_grid(at, grid_w, grid_h));
  comp.render_eye(0, in);
  if (ms) {
    // Median of 5 timed frames after the first (which compiled the programs and made the levels).
    std::vector<double> t;
    for (int k = 0; k < 5; ++k) t.push_back(finished_wall_ms([&] { comp.render_eye(0, in); }));
    std::nth_element(t.begin(), t.begin() + 2, t.end());
    *ms = t[2];
  }
  return test::bgr_clamped(comp.read_eye_buffer(0));
}

cv::Mat cpu_eye(const cv::Mat& eq_bgr, const effects::ParamsAt& at) {
  cv::Mat eq_rgb, ref;
  cv::cvtColor(eq_bgr, eq_rgb, cv::COLOR_BGR2RGB);
  const effects::EquirectSampler sampler(
      eq_rgb, {effects::SampleFilter::Bilinear, effects::PoleRows::Clamp});
  const effects::ViewCamera cam = effects::ViewCamera::from_horizontal_fov(kPose, kFov, kW, kH);
  cv::cvtColor(effects::render_view(sampler, cam, at, effects::RenderMode::Pixel), ref,
               cv::COLOR_RGB2BGR);
  cv::min(cv::max(ref, 0.0), 1.0, ref);
  return ref;
}

// Smooth parameters that vary across the 50-degree view in every effect but blur.
StackParams smooth_params(const Direction& d) {
  const double a = d.azimuth_deg * effects::kDegToRad, h = d.altitude_deg * effects::kDegToRad;
  StackParams p;
  p.set(EffectType::Tint,
        std::vector<double>{1.0 + 0.4 * std::sin(a), 1.0, 1.0 - 0.3 * std::cos(h + a)});
  p.exposure_stops = 0.8 * std::sin(2.0 * a);
  p.saturation = 1.0 + 0.6 * std::cos(3.0 * a);
  p.contrast = 1.0 + 0.3 * std::sin(2.0 * h - a);
  p.vignette_radius_deg = 15.0 + 8.0 * std::sin(2.0 * a);
  p.vignette_falloff_deg = 20.0 + 5.0 * std::cos(a);
  return p;
}

TEST_F(PerPixelGlTest, ColourEffectsAndVignetteMatchTheCpuPixelRender) {
  // Bilinear interpolation of a parameter f on cells of h radians errs by at most h^2 / 8 max|f''|:
  // at 256 x 128 (h = 1.41 deg = 0.0245 rad) and |f''| <= 3.2 stops/rad^2 (exposure) that is
  // 2.4e-4 stops, far below the 8-bit step; the GPU side then matches as the view mode does
  // (<= 2/255, effect_stack_gl_test.cpp). A 16 x 8 grid (h = 22.5 deg) must be visibly worse.
  const cv::Mat eq = test::sunrise_float();
  const unsigned mask = effects::kAllEffectsMask & ~effects::shader_bit(EffectType::Blur);
  const cv::Mat ref = cpu_eye(eq, smooth_params);
  const struct {
    int w, h;
    double max_tolerance;  //!< < 0: only printed, must exceed the fine grid's error
  } grids[] = {{256, 128, 2.0 / 255}, {1024, 512, 2.0 / 255}, {64, 32, -1}, {16, 8, -1}};
  double fine = 0.0;
  for (const auto& g : grids) {
    const test::ErrorStats e =
        test::compare(gpu_eye(eq, smooth_params, mask, true, g.w, g.h, BlurMethod::Exact), ref);
    std::printf("[ per-pixel] grid %4dx%-4d vs CPU pixel mode: max %.3f/255 mean %.4f/255\n", g.w,
                g.h, e.max * 255, e.mean * 255);
    if (g.max_tolerance > 0) {
      EXPECT_LE(e.max, g.max_tolerance) << g.w;
      fine = std::max(fine, e.max);
    } else if (g.w == 16) {
      EXPECT_GT(e.max, fine) << "a coarse grid should err more";
    }
  }
  // View mode (one parameter set for the view) is far from the per-pixel reference.
  const test::ErrorStats view =
      test::compare(gpu_eye(eq, smooth_params, mask, false, 0, 0, BlurMethod::Exact), ref);
  std::printf("[ per-pixel] view mode vs CPU pixel mode: max %.3f/255 mean %.4f/255\n",
              view.max * 255, view.mean * 255);
  EXPECT_GT(view.mean, 4.0 / 255);
}

// Effects only on the left of azimuth 0 (the view straddles it): per-pixel mode must apply them
// there and leave the right half alone, where view mode (parameters at the view's centre, on the
// left) applies them everywhere.
TEST_F(PerPixelGlTest, BlurAndVignetteFollowEachPixelsOwnParameters) {
  const cv::Mat eq = test::sunrise_float();
  const struct {
    const char* name;
    std::function<void(StackParams&)> set;
    double tolerance;  //!< GPU vs CPU per-pixel (blur: measured <= 0.27/255, half-octave levels)
  } cases[] = {
      {"vignette 5/10",
       [](StackParams& p) {
         p.vignette_radius_deg = 5;
         p.vignette_falloff_deg = 10;
       },
       2.0 / 255},
      {"blur 1.5 deg", [](StackParams& p) { p.blur_sigma_deg = 1.5; }, 1.0 / 255},
      {"blur 3 deg", [](StackParams& p) { p.blur_sigma_deg = 3.0; }, 1.0 / 255},
  };
  // Columns of the right half, away from the edge (the grid smooths it over one cell, 1.4 deg, and
  // a blur reaches 3 sigma across it).
  const RenderView v = RenderView::look_at(kPose.look, kPose.roll_deg, kFov, kW, kH);
  cv::Mat right(kH, kW, CV_8U, cv::Scalar(0)), left(kH, kW, CV_8U, cv::Scalar(0));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double az = effects::from_unit(v.world_ray(x + 0.5, y + 0.5, kW, kH)).azimuth_deg;
      if (az > 12.0) right.at<uchar>(y, x) = 255;
      if (az < -3.0) left.at<uchar>(y, x) = 255;
    }
  ASSERT_GT(cv::countNonZero(right), 1000);
  for (const BlurMethod method : {BlurMethod::Exact, BlurMethod::Pyramid})
    for (const auto& c : cases) {
      const effects::ParamsAt at = [&](const Direction& d) {
        StackParams p;
        if (d.azimuth_deg < 0) c.set(p);
        return p;
      };
      StackParams on;
      c.set(on);
      const unsigned mask = effects::non_neutral_mask(on);
      const cv::Mat plain = gpu_eye(eq, at, 0, false, 0, 0, method);
      const cv::Mat gpu = gpu_eye(eq, at, mask, true, 256, 128, method);
      const cv::Mat view = gpu_eye(eq, at, mask, false, 0, 0, method);
      const cv::Mat ref = cpu_eye(eq, at);
      const test::ErrorStats e_left = test::compare(gpu, ref, left);
      const test::ErrorStats e_right = test::compare(gpu, ref, right);
      const test::ErrorStats effect = test::compare(ref, plain, left);
      std::printf(
          "[ per-pixel] %-7s %-13s GPU vs CPU pixel mode: left max %.3f/255 mean %.4f/255, "
          "right max %.3f/255; effect on the left: mean %.2f/255\n",
          std::string(blur_method_name(method)).c_str(), c.name, e_left.max * 255,
          e_left.mean * 255, e_right.max * 255, effect.mean * 255);
      EXPECT_LE(e_left.max, c.tolerance) << c.name;
      EXPECT_LE(e_right.max, 2.0 / 255) << c.name;
      EXPECT_GT(effect.mean, 3.0 / 255) << c.name << ": the case must change the left half";
      // View mode applies the centre's parameters to the right half too.
      EXPECT_GT(test::compare(view, plain, right).mean, 1.0 / 255) << c.name;
    }
}

// The per-pixel blur mixes two uniformly blurred levels around each pixel's sigma; the mixture of
// two Gaussians is not a Gaussian, and the closer the levels the smaller that error. Sigma varies
// smoothly over the view here (0 at the left edge to 3 deg at the right), so every pixel sits at
// some other place between two levels. Errors against the CPU gather and times per spacing are
// printed (docs/compositor.md); the default spacing must be the more accurate one.
TEST_F(PerPixelGlTest, HalfOctaveLevelsBlurCloserToTheCpuGatherThanOctaves) {
  const cv::Mat eq = test::sunrise_float();
  const effects::ParamsAt at = [](const Direction& d) {
    StackParams p;
    p.blur_sigma_deg = std::clamp((d.azimuth_deg + 36.0) / 52.0 * 3.0, 0.0, 3.0);
    return p;
  };
  const cv::Mat ref = cpu_eye(eq, at);
  const unsigned mask = effects::shader_bit(EffectType::Blur);
  const struct {
    const char* name;
    double ratio;
  } spacings[] = {{"octaves (r = 2)", kOctaveLevels},
                  {"half octaves (r = sqrt 2)", kHalfOctaveLevels}};
  for (const BlurMethod method : {BlurMethod::Exact, BlurMethod::Pyramid}) {
    test::ErrorStats e[2];
    for (int k = 0; k < 2; ++k) {
      double ms = 0.0;
      const cv::Mat gpu = gpu_eye(eq, at, mask, true, 256, 128, method, spacings[k].ratio, &ms);
      e[k] = test::compare(gpu, ref);
      std::printf(
          "[ per-pixel] blur 0..3 deg, %-7s levels, %-25s: max %.3f/255 mean %.4f/255, "
          "%.2f ms/eye (200x150, median of 5)\n",
          std::string(blur_method_name(method)).c_str(), spacings[k].name, e[k].max * 255,
          e[k].mean * 255, ms);
    }
    EXPECT_LT(e[1].mean, e[0].mean) << blur_method_name(method);
    EXPECT_LE(e[1].max, e[0].max) << blur_method_name(method);
  }
  EXPECT_EQ(CompositorConfig{}.blur_level_ratio, kHalfOctaveLevels) << "keep the better default";
}

}  // namespace
}  // namespace vdfx::xr
