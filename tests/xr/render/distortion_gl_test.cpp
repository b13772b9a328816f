/// @file
/// @brief Lens pre-distortion: round trip through the simulated lens, mesh error against the
/// per-pixel inverse, LCA fringe cancellation, black beyond the valid radius.
#include "xr/render/distortion_gl.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "effects/distortion_mesh.h"
#include "gl_test_support.h"
#include "xr/render/video_layer.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

constexpr int kSize = 320;

// An asymmetric eye (more FOV on the nasal side): the lens centre, on the optical axis, is off
// the panel centre.
RenderView eye_view() {
  RenderView v = RenderView::look_at({20, 5}, 0, 90.0, kSize, kSize);
  v.tan_left = -1.08;
  v.tan_right = 0.92;
  v.tan_down = -0.96;
  v.tan_up = 1.04;
  return v;
}

effects::LensModel test_lens(std::array<double, 3> lca = {1, 1, 1}) {
  effects::LensParams p;
  p.c1 = 0.22;
  p.c2 = 0.24;
  p.lca_scale = lca;
  return effects::LensModel(p);
}

// Pixels of the wearer's view whose panel point (every channel) lies at least `margin` pixels
// inside the panel: elsewhere the wearer sees black by design.
cv::Mat seen_mask(const RenderView& v, const effects::LensModel& lens, double margin) {
  cv::Mat m(kSize, kSize, CV_8U, cv::Scalar(0));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      bool ok = true;
      for (int c = 0; c < 3; ++c) {
        const auto t = lens.view_to_panel(v.tangent_at(x + 0.5, y + 0.5, kSize, kSize), c);
        if (!t) {
          ok = false;
          continue;
        }
        const Eigen::Vector2d p = v.pixel_at(*t, kSize, kSize);
        ok = ok && p.x() > margin && p.y() > margin && p.x() < kSize - margin &&
             p.y() < kSize - margin;
      }
      m.at<uchar>(y, x) = ok ? 255 : 0;
    }
  return m;
}

double percentile_error(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask, double q) {
  std::vector<float> v;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x)
      if (mask.at<uchar>(y, x))
        for (int c = 0; c < 3; ++c)
          v.push_back(std::abs(a.at<cv::Vec3f>(y, x)[c] - b.at<cv::Vec3f>(y, x)[c]));
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<size_t>(k)];
}

class DistortionGlTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    layer_ = std::make_unique<VideoLayerGl>();
    layer_->set_frame(test::sunrise_float());
    eye_buffer_ = GlTarget(kSize, kSize, TexFormat::RGBA16F);
    layer_->render(eye_buffer_, eye_view());
  }
  std::unique_ptr<VideoLayerGl> layer_;
  GlTarget eye_buffer_;
};

TEST_F(DistortionGlTest, ThroughTheLensOfThePreDistortedImageReproducesTheImage) {
  DistortionGl dist;
  GlTarget panel(kSize, kSize, TexFormat::RGBA16F), seen(kSize, kSize, TexFormat::RGBA16F);
  const effects::LensModel lens = test_lens();
  const cv::Mat original = test::bgr_clamped(eye_buffer_.read_float());
  const cv::Mat mask = seen_mask(eye_view(), lens, 2.0);
  ASSERT_GT(cv::countNonZero(mask), kSize * kSize / 2);
  // Without pre-distortion the lens visibly warps the image: the error the passes must remove.
  dist.through_lens(eye_buffer_.texture(), seen, eye_view(), lens);
  const test::ErrorStats raw = test::compare(test::bgr_clamped(seen.read_float()), original, mask);
  std::printf("[ lens     ] no pre-distortion: max %.2f/255 mean %.3f/255\n", raw.max * 255,
              raw.mean * 255);
  const struct {
    const char* name;
    DistortionSettings s;
  } rows[] = {{"pixel", {DistortionMethod::Pixel, 0, 8, true, false}},
              {"mesh 65", {DistortionMethod::Mesh, 65, 0, true, false}}};
  for (const auto& r : rows) {
    dist.predistort(eye_buffer_.texture(), panel, eye_view(), lens, r.s);
    dist.through_lens(panel.texture(), seen, eye_view(), lens);
    const cv::Mat got = test::bgr_clamped(seen.read_float());
    const test::ErrorStats e = test::compare(got, original, mask);
    const double p99 = percentile_error(got, original, mask, 0.99);
    std::printf("[ lens     ] round trip %-8s max %.2f/255 p99 %.2f/255 mean %.3f/255\n", r.name,
                e.max * 255, p99 * 255, e.mean * 255);
    // Two bilinear resamplings of real content, and where the panel compresses the image (its
    // edge) detail finer than a panel pixel is lost as on a real headset: the sun's hard edge
    // gives the max. The bulk of the image must come back nearly exact.
    EXPECT_LT(e.mean, 1.0 / 255) << r.name;
    EXPECT_LT(p99, 8.0 / 255) << r.name;
    EXPECT_LT(e.mean, raw.mean / 5) << r.name;
  }
}

TEST_F(DistortionGlTest, MeshSamplePositionErrorFallsAsTheGridGrows) {
  DistortionGl dist;
  GlTarget uv(kSize, kSize, TexFormat::RG32F);
  const effects::LensModel lens = test_lens();
  DistortionSettings exact{DistortionMethod::Pixel, 0, 30, true, true};
  dist.predistort(eye_buffer_.texture(), uv, eye_view(), lens, exact);
  const cv::Mat ref = uv.read_float();
  double last_rms = 1e9;
  for (int n : {5, 9, 17, 33, 65}) {
    dist.predistort(eye_buffer_.texture(), uv, eye_view(), lens,
                    {DistortionMethod::Mesh, n, 0, true, true});
    const cv::Mat got = uv.read_float();
    double sum2 = 0, mx = 0, count = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const cv::Vec2f a = ref.at<cv::Vec2f>(y, x), b = got.at<cv::Vec2f>(y, x);
        const double e = std::hypot(a[0] - b[0], a[1] - b[1]);
        sum2 += e * e;
        mx = std::max(mx, e);
        count += 1;
      }
    const double rms = std::sqrt(sum2 / count);
    std::printf("[ lens     ] mesh %2dx%-2d sample position error: RMS %.4f px, max %.4f px\n", n,
                n, rms, mx);
    EXPECT_LT(rms, last_rms) << "N = " << n;
    last_rms = rms;
  }
  EXPECT_LT(last_rms, 0.05);  // 65x65: far below a pixel
}

TEST_F(DistortionGlTest, InverseLcaMakesTheColourFringesCancel) {
  // Grey content: any difference between red and blue the wearer sees is a colour fringe.
  cv::Mat grey = test::bgr_clamped(eye_buffer_.read_float());
  cv::cvtColor(grey, grey, cv::COLOR_BGR2GRAY);
  cv::cvtColor(grey, grey, cv::COLOR_GRAY2BGR);
  GlTexture src(kSize, kSize, TexFormat::RGBA32F);
  src.upload(grey);
  const effects::LensModel lens = test_lens({0.985, 1.0, 1.015});  // OpenHMD's DK2 values
  const cv::Mat mask = seen_mask(eye_view(), lens, 2.0);
  DistortionGl dist;
  GlTarget panel(kSize, kSize, TexFormat::RGBA16F), seen(kSize, kSize, TexFormat::RGBA16F);
  const auto fringe = [&](DistortionSettings s) {
    dist.predistort(src, panel, eye_view(), lens, s);
    dist.through_lens(panel.texture(), seen, eye_view(), lens);
    const cv::Mat img = test::bgr_clamped(seen.read_float());
    std::vector<cv::Mat> ch;
    cv::split(img, ch);
    cv::Mat d;
    cv::absdiff(ch[0], ch[2], d);
    return cv::mean(d, mask)[0];
  };
  for (DistortionMethod m : {DistortionMethod::Pixel, DistortionMethod::Mesh}) {
    const double off = fringe({m, 65, 8, false, false});
    const double on = fringe({m, 65, 8, true, false});
    std::printf(
        "[ lens     ] %s: mean |R - B| fringe without LCA correction %.3f/255, with %.3f/255\n",
        m == DistortionMethod::Pixel ? "pixel" : "mesh", off * 255, on * 255);
    EXPECT_GT(off, 2.0 / 255);
    EXPECT_LT(on, off / 8);
  }
}

TEST_F(DistortionGlTest, BeyondTheValidRadiusThePanelIsBlackNotFolded) {
  effects::LensParams lp;
  lp.c1 = -0.25;  // f' = 1 - 0.75 r^2 reaches 0 at r = 1.1547: r_d max = 0.7698
  const effects::LensModel lens(lp);
  ASSERT_NEAR(lens.max_distorted_radius(), 2.0 / 3.0 * std::sqrt(4.0 / 3.0), 1e-12);
  GlTexture white(kSize, kSize, TexFormat::RGBA32F);
  white.upload(cv::Mat(kSize, kSize, CV_32FC3, cv::Scalar::all(1.0)));
  DistortionGl dist;
  GlTarget panel(kSize, kSize, TexFormat::RGBA16F);
  RenderView v = RenderView::look_at({0, 0}, 0, 110.0, kSize, kSize);  // corners at r = 2.0
  for (DistortionMethod m : {DistortionMethod::Pixel, DistortionMethod::Mesh}) {
    dist.predistort(white, panel, v, lens, {m, 65, 8, true, false});
    const cv::Mat img = test::bgr_clamped(panel.read_float());
    int wrong = 0, checked = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double rd = v.tangent_at(x + 0.5, y + 0.5, kSize, kSize).norm();
        const float g = img.at<cv::Vec3f>(y, x)[1];
        if (rd > 0.79) {
          ++checked;
          wrong += g != 0.0f;
        } else if (rd < 0.75) {
          ++checked;
          wrong += g < 0.999f;
        }
      }
    EXPECT_GT(checked, kSize * kSize * 9 / 10);
    EXPECT_EQ(wrong, 0) << (m == DistortionMethod::Pixel ? "pixel" : "mesh");
  }
}

}  // namespace
}  // namespace vdfx::xr
