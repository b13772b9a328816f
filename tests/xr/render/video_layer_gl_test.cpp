/// @file
/// @brief The equirect video layer against a CPU sample of the same ray, and mip selection at the
/// poles against a supersampled reference.
#include <gtest/gtest.h>

#include <cstdio>

#include "effects/coords.h"
#include "effects/equirect_sampler.h"
#include "gl_test_support.h"
#include "xr/render/gl_texture.h"
#include "xr/render/video_layer.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

// The CPU reference sampler (effects/equirect_sampler.h, level-0 bilinear, rows clamped like
// GL's CLAMP_TO_EDGE) on the RGB version of the image; returns BGR.
cv::Vec3f sample_ray(const effects::EquirectSampler& sampler, const Eigen::Vector3d& ray) {
  const Eigen::Vector3d c = sampler.sample(ray);
  return cv::Vec3f(static_cast<float>(c.z()), static_cast<float>(c.y()), static_cast<float>(c.x()));
}

// CPU render: `ss` x `ss` samples per pixel, box-filtered (ss = 1: one sample at the centre).
cv::Mat cpu_render(const cv::Mat& equirect_bgr, const RenderView& v, int w, int h, int ss) {
  cv::Mat rgb;
  cv::cvtColor(equirect_bgr, rgb, cv::COLOR_BGR2RGB);
  const effects::EquirectSampler equirect(
      rgb, {effects::SampleFilter::Bilinear, effects::PoleRows::Clamp});
  cv::Mat out(h, w, CV_32FC3);
  out.forEach<cv::Vec3f>([&](cv::Vec3f& px, const int* pos) {
    cv::Vec3d acc(0, 0, 0);
    for (int sy = 0; sy < ss; ++sy)
      for (int sx = 0; sx < ss; ++sx)
        acc += cv::Vec3d(sample_ray(
            equirect, v.world_ray(pos[1] + (sx + 0.5) / ss, pos[0] + (sy + 0.5) / ss, w, h)));
    acc /= static_cast<double>(ss * ss);
    px = cv::Vec3f(static_cast<float>(acc[0]), static_cast<float>(acc[1]),
                   static_cast<float>(acc[2]));
  });
  return out;
}

double rms(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  return std::sqrt(cv::mean(d.mul(d))[0] / 3 + cv::mean(d.mul(d))[1] / 3 +
                   cv::mean(d.mul(d))[2] / 3);
}

class VideoLayerGlTest : public GlTest {};

const struct {
  const char* name;
  effects::Direction look;
  double roll_deg;
} kViews[] = {
    {"ahead", {0, 10}, 0},
    {"across the seam, rolled", {180, -5}, 25},
    {"left and down", {-100, -35}, -10},
};

TEST_F(VideoLayerGlTest, MatchesACpuBilinearSampleOfTheSameRay) {
  const cv::Mat eq = test::sunrise_float();
  VideoLayerGl layer;
  layer.set_frame(eq);
  // 420 px over 60 degrees is 7 px/degree; the texture has 2.8 texels/degree on the horizon and
  // 2.8 / cos(alt) along rows, below 7 up to |alt| = 66: magnified everywhere, level 0.
  const int w = 420, h = 336;
  GlTarget dst(w, h, TexFormat::RGBA32F);
  for (const auto& row : kViews) {
    const RenderView v = RenderView::look_at(row.look, row.roll_deg, 60.0, w, h);
    const cv::Mat ref = cpu_render(eq, v, w, h, 1);
    for (LodMode mode : {LodMode::Analytic, LodMode::Derivatives}) {
      layer.render(dst, v, mode);
      const test::ErrorStats e = test::compare(test::bgr_clamped(dst.read_float()), ref);
      std::printf("[ video    ] %-24s lod %d: max %.3f/255 mean %.4f/255\n", row.name,
                  static_cast<int>(mode), e.max * 255, e.mean * 255);
      EXPECT_LE(e.max, 2.0 / 255) << row.name << " lod mode " << static_cast<int>(mode);
    }
  }
}

TEST_F(VideoLayerGlTest, PolesDoNotAliasAgainstASupersampledReference) {
  // 2-texel checks: far finer than the view resolves near the pole, where a ring of the
  // equirect shrinks to a point. Without mips the sampler picks texels at random-looking phase.
  const int W = 2048, H = 1024;
  cv::Mat checks(H, W, CV_32FC3);
  checks.forEach<cv::Vec3f>([](cv::Vec3f& px, const int* pos) {
    const float c = ((pos[0] / 2 + pos[1] / 2) % 2) ? 0.9f : 0.1f;
    px = cv::Vec3f(c, c, c);
  });
  VideoLayerGl layer;
  layer.set_frame(checks);
  const int w = 128, h = 128;
  GlTarget dst(w, h, TexFormat::RGBA32F);
  const RenderView v = RenderView::look_at({30, 80}, 0, 90.0, w, h);
  const cv::Mat ref = cpu_render(checks, v, w, h, 12);
  double err[3] = {};
  for (LodMode mode : {LodMode::Analytic, LodMode::Derivatives, LodMode::Base}) {
    layer.render(dst, v, mode);
    err[static_cast<int>(mode)] = rms(test::bgr_clamped(dst.read_float()), ref);
  }
  std::printf(
      "[ video    ] pole view RMS vs 12x12 supersampled: analytic %.4f, derivatives %.4f, "
      "base level %.4f\n",
      err[0], err[1], err[2]);
  // The aliasing of the base level is the 0.4 amplitude of the checks; mipmapping must remove most.
  EXPECT_GT(err[2], 0.15);
  EXPECT_LT(err[0], err[2] / 3);
  EXPECT_LT(err[1], err[2] / 3);
}

TEST_F(VideoLayerGlTest, SeamColumnDoesNotPickTheSmallestMip) {
  // A view straight across the seam on fine checks that the view resolves (magnified): a seam
  // column sampled at the 1x1 mip would be flat grey, differing from the reference by ~0.4.
  const int W = 512, H = 256;
  cv::Mat checks(H, W, CV_32FC3);
  checks.forEach<cv::Vec3f>([](cv::Vec3f& px, const int* pos) {
    const float c = ((pos[0] / 4 + pos[1] / 4) % 2) ? 0.9f : 0.1f;
    px = cv::Vec3f(c, c, c);
  });
  VideoLayerGl layer;
  layer.set_frame(checks);
  const int w = 200, h = 100;
  GlTarget dst(w, h, TexFormat::RGBA32F);
  const RenderView v = RenderView::look_at({180, 0}, 0, 40.0, w, h);
  const cv::Mat ref = cpu_render(checks, v, w, h, 1);
  for (LodMode mode : {LodMode::Analytic, LodMode::Derivatives}) {
    layer.render(dst, v, mode);
    const cv::Mat gpu = test::bgr_clamped(dst.read_float());
    const cv::Rect seam(w / 2 - 2, 0, 4, h);
    const test::ErrorStats e = test::compare(gpu(seam), ref(seam));
    EXPECT_LE(e.max, 2.0 / 255) << "lod mode " << static_cast<int>(mode);
  }
}

}  // namespace
}  // namespace vdfx::xr
