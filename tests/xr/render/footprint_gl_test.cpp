/// @file
/// @brief The footprint filter on the GPU (the video layer's default) against the CPU reference
/// (effects::EquirectSampler) on a table of views: the seam, both poles, fields of view 30..150,
/// sizes 64x48..640x480; both against the supersampled truth (the same view at 8x the size,
/// area-averaged down), beside the older samplings; and the GPU's mip chain against the CPU's.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "effects/equirect_sampler.h"
#include "effects/mip_chain.h"
#include "effects/view_renderer.h"
#include "gl_test_support.h"
#include "xr/render/gl_texture.h"
#include "xr/render/mip_chain_gl.h"
#include "xr/render/video_layer.h"

namespace vdfx::xr {
namespace {

using test::GlTest;
class FootprintGlTest : public GlTest {};

/// 1024x512 RGB float: Blender's sunrise with one-texel checks over its top and bottom eighth
/// (detail no view near a pole resolves) and fine stripes along the seam.
const cv::Mat& panorama_rgb() {
  static const cv::Mat m = [] {
    cv::Mat rgb;
    cv::cvtColor(test::sunrise_float(), rgb, cv::COLOR_BGR2RGB);
    rgb.forEach<cv::Vec3f>([&](cv::Vec3f& px, const int* pos) {
      const int y = pos[0], x = pos[1];
      const bool cap = y < rgb.rows / 8 || y >= rgb.rows - rgb.rows / 8;
      const bool seam = x < 6 || x >= rgb.cols - 6;
      if (cap) px = cv::Vec3f::all(((x + y) % 2) ? 0.85f : 0.15f) * 0.5f + px * 0.5f;
      if (seam) px[1] = (y / 2) % 2 ? 0.9f : 0.1f;
    });
    return rgb;
  }();
  return m;
}

cv::Mat gpu_view(VideoLayerGl& layer, const RenderView& v, int w, int h, LodMode mode) {
  GlTarget dst(w, h, TexFormat::RGBA32F);
  layer.render(dst, v, mode);
  cv::Mat rgb;
  cv::cvtColor(dst.read_float(), rgb, cv::COLOR_BGRA2RGB);
  return rgb;
}

/// The truth: each pixel the mean of k x k level-0 bilinear samples spread over its square
/// (the view rendered at k times the size, area-averaged down).
cv::Mat supersampled(const cv::Mat& rgb, const effects::ViewCamera& cam, int k) {
  const effects::EquirectSampler s(rgb, {effects::SampleFilter::Bilinear});
  cv::Mat out(cam.height(), cam.width(), CV_32FC3);
  out.forEach<cv::Vec3f>([&](cv::Vec3f& px, const int* pos) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int b = 0; b < k; ++b)
      for (int a = 0; a < k; ++a)
        sum += s.sample(cam.ray(pos[1] + (a + 0.5) / k, pos[0] + (b + 0.5) / k));
    sum /= k * k;
    px = cv::Vec3f(static_cast<float>(sum.x()), static_cast<float>(sum.y()),
                   static_cast<float>(sum.z()));
  });
  return out;
}

/// Max and mean of |a - b| in 8-bit steps after each is rounded to 8 bits (the output step).
test::ErrorStats steps(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat a8, b8;
  effects::to_rgb8(a).convertTo(a8, CV_32F);
  effects::to_rgb8(b).convertTo(b8, CV_32F);
  return test::compare(a8, b8);
}

double rms_steps(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat d = (a - b) * 255.0;
  const cv::Mat sq = d.mul(d);
  return std::sqrt(cv::mean(sq.reshape(1))[0]);
}

const struct ViewCase {
  const char* name;
  effects::Direction look;
  double roll_deg, fov;
  int w, h;
  bool stretched;  //!< footprints long and thin (near a pole) over much of the view
} kViews[] = {
    {"horizon", {20, 0}, 0, 90, 64, 48, false},
    {"seam, rolled", {180, 5}, 10, 60, 160, 120, false},
    {"seam, wide", {-180, -20}, 0, 150, 64, 48, true},
    {"zenith", {0, 90}, 0, 120, 320, 240, true},
    {"zenith, pole on a pixel centre", {0, 90}, 0, 90, 65, 49, true},
    {"nadir, rolled", {30, -90}, 15, 120, 320, 240, true},
    {"altitude -60", {0, -60}, 0, 60, 320, 240, true},
    {"narrow", {45, 30}, 0, 30, 64, 48, false},
    {"wide, low", {-60, -40}, 0, 150, 640, 480, true},
    {"nadir, large", {0, -90}, 0, 120, 640, 480, true},
    {"near the zenith, large", {100, 75}, -20, 60, 640, 480, true},
};

TEST_F(FootprintGlTest, GpuMatchesTheCpuReferenceOnEveryView) {
  VideoLayerGl layer;
  cv::Mat bgr;
  cv::cvtColor(panorama_rgb(), bgr, cv::COLOR_RGB2BGR);
  layer.set_frame(bgr);
  const effects::EquirectSampler cpu(panorama_rgb());
  for (const ViewCase& c : kViews) {
    const RenderView v = RenderView::look_at(c.look, c.roll_deg, c.fov, c.w, c.h);
    const cv::Mat ref = effects::sample_view(cpu, v.camera(c.w, c.h));
    const cv::Mat gpu = gpu_view(layer, v, c.w, c.h, LodMode::Footprint);
    const test::ErrorStats e = steps(gpu, ref);
    std::printf("[ footprint ] %-32s fov %3.0f %4dx%-4d GPU vs CPU: max %.0f mean %.4f /255\n",
                c.name, c.fov, c.w, c.h, e.max, e.mean);
    EXPECT_LE(e.max, 2.0) << c.name;
  }
}

TEST_F(FootprintGlTest, BothAreCloserToTheSupersampledTruthThanPointSampling) {
  // Measured (RMS in 8-bit steps, footprint CPU = GPU / point / isotropic mip): horizon 2.60 /
  // 4.60 / 2.84, seam rolled 1.38 / 2.07 / 1.25, seam wide 1.48 / 7.05 / 2.92, zenith 0.53 /
  // 3.56 / 1.46, nadir rolled 0.91 / 4.32 / 2.50, altitude -60 0.95 / 5.82 / 2.25.
  VideoLayerGl layer;
  cv::Mat bgr;
  cv::cvtColor(panorama_rgb(), bgr, cv::COLOR_RGB2BGR);
  layer.set_frame(bgr);
  const effects::EquirectSampler cpu(panorama_rgb());
  const effects::EquirectSampler point(panorama_rgb(), {effects::SampleFilter::Bilinear});
  for (const ViewCase& c : kViews) {
    if (c.w > 320) continue;  // the 8x truth of a 640x480 view is 20 million samples
    const RenderView v = RenderView::look_at(c.look, c.roll_deg, c.fov, c.w, c.h);
    const effects::ViewCamera cam = v.camera(c.w, c.h);
    const cv::Mat truth = supersampled(panorama_rgb(), cam, 8);
    const double e_cpu = rms_steps(effects::sample_view(cpu, cam), truth);
    const double e_gpu = rms_steps(gpu_view(layer, v, c.w, c.h, LodMode::Footprint), truth);
    const double e_point = rms_steps(effects::sample_view(point, cam), truth);
    const double e_iso = rms_steps(gpu_view(layer, v, c.w, c.h, LodMode::Analytic), truth);
    const double e_base = rms_steps(gpu_view(layer, v, c.w, c.h, LodMode::Base), truth);
    std::printf(
        "[ footprint ] %-32s RMS vs 8x truth /255: CPU %.2f GPU %.2f | CPU point %.2f, "
        "GPU isotropic mip %.2f, GPU base level %.2f\n",
        c.name, e_cpu, e_gpu, e_point, e_iso, e_base);
    // Point sampling aliases wherever the view shrinks the image (RMS 3.5..7 here); the
    // footprint stays within about half of that plus one step everywhere ...
    EXPECT_LT(e_cpu, 0.5 * e_point + 1.0) << c.name;
    EXPECT_LT(e_gpu, 0.5 * e_point + 1.0) << c.name;
    // ... and where footprints are long and thin, closer than the isotropic mip level too.
    if (c.stretched) {
      EXPECT_LT(e_gpu, e_iso) << c.name;
    }
  }
}

/// Level `l` of a texture, read back as float (any format), upright.
cv::Mat read_level(unsigned tex, int l, int w, int h, int channels) {
  cv::Mat m(h, w, CV_32FC(channels));
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_2D, l, channels == 1 ? GL_RED : GL_RGB, GL_FLOAT, m.data);
  cv::Mat up;
  cv::flip(m, up, 0);
  return up;
}

TEST_F(FootprintGlTest, GpuMipChainIsTheCpuChain) {
  // Odd sides at several levels (45 -> 22 -> 11 -> 5 -> 2 -> 1, 23 -> 11 -> 5 -> 2 -> 1).
  cv::Mat img(23, 45, CV_32FC3);
  cv::theRNG().state = 7;
  cv::randu(img, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  for (const TexFormat format : {TexFormat::RGBA32F, TexFormat::RGBA8}) {
    const bool bytes = format == TexFormat::RGBA8;
    GlTexture tex(img.cols, img.rows, format, full_mip_levels(img.cols, img.rows));
    cv::Mat bgr, level0;
    cv::cvtColor(img, bgr, cv::COLOR_RGB2BGR);
    if (bytes) bgr.convertTo(bgr, CV_8UC3, 255.0);
    tex.upload(bgr);
    cv::cvtColor(bgr, level0, cv::COLOR_BGR2RGB);
    level0.convertTo(level0, CV_32FC3, bytes ? 1.0 / 255 : 1.0);
    const std::vector<cv::Mat> cpu = effects::build_mip_chain(level0);
    ASSERT_EQ(tex.levels(), static_cast<int>(cpu.size()));
    MipChainGl().build(tex.id(), tex.width(), tex.height(), tex.levels());
    for (int l = 1; l < tex.levels(); ++l) {
      // An 8-bit level is rounded once more than the one above: half a step per level at most.
      const double tolerance = bytes ? (0.5 * l + 0.01) / 255 : 1e-5;
      const cv::Mat got = read_level(tex.id(), l, cpu[static_cast<std::size_t>(l)].cols,
                                     cpu[static_cast<std::size_t>(l)].rows, 3);
      EXPECT_LT(cv::norm(got, cpu[static_cast<std::size_t>(l)], cv::NORM_INF), tolerance)
          << "level " << l << (format == TexFormat::RGBA8 ? " (RGBA8)" : " (RGBA32F)");
    }
  }
}

}  // namespace
}  // namespace vdfx::xr
