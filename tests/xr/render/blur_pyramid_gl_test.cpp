/// @file
/// @brief The pyramid blur against the exact separable blur: the plan's arithmetic, and error
/// and time for sigma 0.5, 1, 2, 4 degrees (printed; only a generous error bound is asserted).
#include "xr/render/blur_pyramid_gl.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "effects/effect_shaders.h"
#include "effects/gaussian_blur.h"
#include "gl_test_support.h"
#include "xr/render/effect_stack_gl.h"
#include "xr/render/gpu_timer.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

TEST(PyramidPlan, HalvesWhileTheLevelSigmaStaysAboveTheMinimumAndKeepsTheVariance) {
  const struct {
    double sigma;
    int halvings;
  } rows[] = {{1.0, 0}, {3.9, 0}, {4.0, 1}, {7.9, 1}, {8.0, 2}, {42.0, 4}, {300.0, 7}};
  for (const auto& r : rows) {
    const PyramidPlan p = plan_pyramid(r.sigma, 1.5 * r.sigma);
    EXPECT_EQ(p.halvings, r.halvings) << r.sigma;
    // Residual variance plus what the halvings and the upsampling add is the requested variance.
    const double s = std::ldexp(1.0, p.halvings);
    const double added = p.halvings ? (s * s - 1.0) / 4.0 + s * s / 6.0 : 0.0;
    EXPECT_NEAR(p.residual_x * p.residual_x * s * s + added, r.sigma * r.sigma, 1e-9) << r.sigma;
    EXPECT_GE(p.residual_x, p.halvings ? 1.5 : 0.0) << r.sigma;
  }
}

class BlurPyramidGlTest : public GlTest {};

TEST_F(BlurPyramidGlTest, TheTapTableKeepsItsTextureWhileTheRadiusChanges) {
  // The per-pixel blur sets one radius per level, per eye, per frame: the table must not be
  // reallocated for each (only grown, by doubling, when a radius needs more than it holds).
  const GlProgram p =
      GlProgram::build("blur_1d", fullscreen_vertex_source(), effects::blur_1d_fragment_source());
  p.use();
  GlTexture taps;
  set_gaussian_uniforms(p, 2.0, effects::gaussian_radius(2.0), 1, taps);
  ASSERT_TRUE(taps);
  const unsigned id = taps.id();
  EXPECT_EQ(taps.width(), kMinTapCapacity);
  for (double sigma : {10.0, 0.7, 40.0, 3.0}) {
    set_gaussian_uniforms(p, sigma, effects::gaussian_radius(sigma), 1, taps);
    EXPECT_EQ(taps.id(), id) << sigma;
    GLint count = -1;
    glGetUniformiv(p.id(), p.uniform("u_tap_count"), &count);
    EXPECT_EQ(count, (effects::gaussian_radius(sigma) + 1) / 2) << sigma;
  }
  set_gaussian_uniforms(p, 100.0, effects::gaussian_radius(100.0), 1, taps);  // 150 pairs
  EXPECT_EQ(taps.width(), 4 * kMinTapCapacity);
}

TEST_F(BlurPyramidGlTest, PyramidStaysCloseToTheExactBlur) {
  // 512 x 512 at 90 degrees: 4.5 px/degree, so sigma 0.5 .. 4 deg is 2.2 .. 18 px (0 .. 3
  // halvings).
  const int n = 512;
  cv::Mat src;
  cv::resize(test::sunrise_float(), src, {n, n}, 0, 0, cv::INTER_AREA);
  GlTexture tex(n, n, TexFormat::RGBA32F);
  tex.upload(src);
  GlTarget exact_out(n, n, TexFormat::RGBA32F), pyr_out(n, n, TexFormat::RGBA32F);
  EffectStackGl exact(TexFormat::RGBA32F, BlurMethod::Exact),
      pyramid(TexFormat::RGBA32F, BlurMethod::Pyramid);
  const RenderView eye = RenderView::look_at({0, 0}, 0, 90, n, n);
  for (const double sigma_deg : {0.5, 1.0, 2.0, 4.0}) {
    effects::StackParams p;
    p.blur_sigma_deg = sigma_deg;
    const unsigned mask = effects::non_neutral_mask(p);
    exact.apply(tex, exact_out, p, mask, eye);  // warm-up: compiles the variants
    pyramid.apply(tex, pyr_out, p, mask, eye);
    const double t_exact = finished_wall_ms([&] { exact.apply(tex, exact_out, p, mask, eye); });
    const double t_pyr = finished_wall_ms([&] { pyramid.apply(tex, pyr_out, p, mask, eye); });
    const cv::Mat a = test::bgr_clamped(exact_out.read_float());
    const cv::Mat b = test::bgr_clamped(pyr_out.read_float());
    const test::ErrorStats e = test::compare(a, b);
    const BlurPixels px = blur_pixels(sigma_deg, eye, n, n);
    std::printf(
        "[ pyramid  ] sigma %.1f deg (%5.1f px, %d halvings): max %.4f mean %.5f "
        "(0..1); exact %.1f ms, pyramid %.1f ms (512 x 512, llvmpipe, one run)\n",
        sigma_deg, px.sigma_x, plan_pyramid(px.sigma_x, px.sigma_y).halvings, e.max, e.mean,
        t_exact, t_pyr);
    EXPECT_LE(e.mean, 1.0 / 255) << sigma_deg;
    EXPECT_LE(e.max, 24.0 / 255) << sigma_deg;  // measured <= 15.6/255, at the HDR sun's edge
    // The blur happened in both: far from the unblurred image.
    EXPECT_GT(test::compare(b, test::bgr_clamped(tex.read_float())).mean, 2.0 / 255) << sigma_deg;
  }
}

}  // namespace
}  // namespace vdfx::xr
