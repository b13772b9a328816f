/// @file
/// @brief The GPU effect stack against the contract's formulas evaluated in double.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "effects/coords.h"
#include "effects/effect_shaders.h"
#include "gl_test_support.h"
#include "xr/effect_stack_gl.h"
#include "xr/gl_texture.h"

namespace vdfx::xr {
namespace {

using effects::EffectType;
using effects::StackParams;
using test::GlTest;

// An asymmetric eye with an off-centre optical centre, so that geometry mistakes show.
RenderView test_eye() {
  RenderView v;
  v.tan_left = -1.1;
  v.tan_right = 0.9;
  v.tan_down = -0.8;
  v.tan_up = 0.7;
  v.optical_centre_tan = {0.05, -0.03};
  return v;
}

cv::Mat test_source(int w, int h) {
  cv::Mat s = test::sunrise_float();
  // A 90-degree-wide band around the horizon keeps sky, sun and ground detail in the crop.
  cv::Mat crop = s(cv::Rect(s.cols / 4, s.rows / 4, s.cols / 2, s.rows / 2)).clone();
  cv::Mat out;
  cv::resize(crop, out, {w, h}, 0, 0, cv::INTER_AREA);
  return out;
}

// 1-D Gaussian along x (axis 0) or y (axis 1), border replicated, weights normalised.
cv::Mat gaussian_1d(const cv::Mat& src, double sigma, int radius, int axis) {
  std::vector<double> w(static_cast<size_t>(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) sum += (w[static_cast<size_t>(i + radius)] = std::exp(-i * i / (2 * sigma * sigma)));
  cv::Mat out(src.size(), CV_64FC3);
  for (int y = 0; y < src.rows; ++y)
    for (int x = 0; x < src.cols; ++x) {
      cv::Vec3d acc(0, 0, 0);
      for (int i = -radius; i <= radius; ++i) {
        const int xx = axis == 0 ? std::clamp(x + i, 0, src.cols - 1) : x;
        const int yy = axis == 1 ? std::clamp(y + i, 0, src.rows - 1) : y;
        acc += w[static_cast<size_t>(i + radius)] * src.at<cv::Vec3d>(yy, xx);
      }
      out.at<cv::Vec3d>(y, x) = acc / sum;
    }
  return out;
}

// The contract's stack in double; image rows run top to bottom (row 0 = top of the view).
cv::Mat reference_stack(const cv::Mat& src_f, const StackParams& p, unsigned mask,
                        const RenderView& v) {
  cv::Mat c;
  src_f.convertTo(c, CV_64FC3);
  const int w = c.cols, h = c.rows;
  if (mask & effects::shader_bit(EffectType::Blur)) {
    const double s = p.blur_sigma_deg * effects::kDegToRad;
    const double cx = v.optical_centre_tan.x(), cy = v.optical_centre_tan.y();
    const double sx = s * (1 + cx * cx) * w / (v.tan_right - v.tan_left);
    const double sy = s * (1 + cy * cy) * h / (v.tan_up - v.tan_down);
    c = gaussian_1d(gaussian_1d(c, sx, static_cast<int>(std::ceil(3 * sx)), 0), sy,
                    static_cast<int>(std::ceil(3 * sy)), 1);
  }
  const Eigen::Vector3d axis(v.optical_centre_tan.x(), v.optical_centre_tan.y(), -1.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      cv::Vec3d& px = c.at<cv::Vec3d>(y, x);
      Eigen::Vector3d rgb(px[2], px[1], px[0]);
      if (mask & effects::shader_bit(EffectType::Tint)) rgb = rgb.cwiseProduct(p.tint_gain);
      if (mask & effects::shader_bit(EffectType::Exposure)) rgb *= std::exp2(p.exposure_stops);
      if (mask & effects::shader_bit(EffectType::Saturation)) {
        const double Y = 0.25 * rgb.x() + 0.5 * rgb.y() + 0.25 * rgb.z();
        rgb = Eigen::Vector3d::Constant(Y) + p.saturation * (rgb - Eigen::Vector3d::Constant(Y));
      }
      if (mask & effects::shader_bit(EffectType::Contrast))
        rgb = Eigen::Vector3d::Constant(0.5) + p.contrast * (rgb - Eigen::Vector3d::Constant(0.5));
      if (mask & effects::shader_bit(EffectType::Vignette)) {
        const Eigen::Vector2d t = v.tangent_at(x + 0.5, y + 0.5, w, h);
        const double d = effects::angle_between({t.x(), t.y(), -1.0}, axis) * effects::kRadToDeg;
        const double R = p.vignette_radius_deg, F = p.vignette_falloff_deg;
        const double f = d <= R ? 1.0 : (d <= R + F ? 1.0 - (d - R) / F : 0.0);
        rgb *= f;
      }
      px = {rgb.z(), rgb.y(), rgb.x()};
    }
  cv::Mat out;
  c.convertTo(out, CV_32FC3);
  cv::min(cv::max(out, 0.0), 1.0, out);
  return out;
}

const struct {
  const char* name;
  std::function<void(StackParams&)> set;
} kCases[] = {
    {"blur 1.5 deg", [](StackParams& p) { p.blur_sigma_deg = 1.5; }},
    {"blur 6 deg", [](StackParams& p) { p.blur_sigma_deg = 6.0; }},
    {"tint", [](StackParams& p) { p.set(EffectType::Tint, std::vector<double>{1.6, 0.8, 0.5}); }},
    {"exposure +1.3", [](StackParams& p) { p.exposure_stops = 1.3; }},
    {"exposure -2", [](StackParams& p) { p.exposure_stops = -2.0; }},
    {"saturation 0.2", [](StackParams& p) { p.saturation = 0.2; }},
    {"saturation 2.5", [](StackParams& p) { p.saturation = 2.5; }},
    {"contrast 1.8", [](StackParams& p) { p.contrast = 1.8; }},
    {"contrast 0.4", [](StackParams& p) { p.contrast = 0.4; }},
    {"vignette 20/15", [](StackParams& p) { p.vignette_radius_deg = 20; p.vignette_falloff_deg = 15; }},
    {"full stack",
     [](StackParams& p) {
       p.blur_sigma_deg = 2.0;
       p.set(EffectType::Tint, std::vector<double>{1.2, 1.0, 0.7});
       p.exposure_stops = 0.7;
       p.saturation = 1.6;
       p.contrast = 1.3;
       p.vignette_radius_deg = 25;
       p.vignette_falloff_deg = 20;
     }},
};

class EffectStackGlTest : public GlTest {};

TEST_F(EffectStackGlTest, EachEffectAndTheFullStackMatchTheContractInDouble) {
  const int w = 240, h = 180;
  const cv::Mat src = test_source(w, h);
  GlTexture src_tex(w, h, TexFormat::RGBA32F);
  src_tex.upload(src);
  GlTarget dst(w, h, TexFormat::RGBA16F);  // the compositor's eye-buffer format
  EffectStackGl stack;
  const RenderView eye = test_eye();
  for (const auto& row : kCases) {
    StackParams p;
    row.set(p);
    const unsigned mask = effects::non_neutral_mask(p);
    ASSERT_NE(mask, 0u) << row.name;
    stack.apply(src_tex, dst, p, mask, eye);
    const cv::Mat gpu = test::bgr_clamped(dst.read_float());
    const cv::Mat ref = reference_stack(src, p, mask, eye);
    const test::ErrorStats e = test::compare(gpu, ref);
    std::printf("[ stack    ] %-16s max %.3f/255  mean %.4f/255\n", row.name, e.max * 255, e.mean * 255);
    EXPECT_LE(e.max, 2.0 / 255.0) << row.name;
    // The effect must have done something measurable, or the comparison proves nothing.
    EXPECT_GT(test::compare(ref, reference_stack(src, StackParams{}, 0, eye)).mean, 1.0 / 255) << row.name;
  }
}

TEST_F(EffectStackGlTest, OnlyTheActiveSetIsCompiledAndVariantsAreCached) {
  const int w = 32, h = 32;
  GlTexture src(w, h, TexFormat::RGBA32F);
  src.upload(cv::Mat(h, w, CV_32FC3, cv::Scalar(0.2, 0.4, 0.6)));
  GlTarget dst(w, h, TexFormat::RGBA16F);
  EffectStackGl stack;
  StackParams p;
  p.exposure_stops = 1.0;
  stack.apply(src, dst, p, effects::non_neutral_mask(p), test_eye());
  stack.apply(src, dst, p, effects::non_neutral_mask(p), test_eye());
  EXPECT_EQ(stack.cached_variants(), 1u);
  p.contrast = 1.5;
  stack.apply(src, dst, p, effects::non_neutral_mask(p), test_eye());
  EXPECT_EQ(stack.cached_variants(), 2u);
  // A variant without exposure compiled in leaves exposure out even if its value is set.
  stack.apply(src, dst, p, effects::shader_bit(EffectType::Contrast), test_eye());
  const cv::Vec4f c = dst.read_float().at<cv::Vec4f>(5, 5);
  EXPECT_NEAR(c[2], 0.5 + 1.5 * (0.6 - 0.5), 1e-3);
  const std::string src_text = effects::stack_fragment_source(effects::shader_bit(EffectType::Contrast));
  EXPECT_NE(src_text.find("#define HAS_EXPOSURE 0"), std::string::npos);
}

TEST_F(EffectStackGlTest, VignetteIsCentredOnTheProjectedOpticalCentreOfAnOffCentreEye) {
  const int w = 400, h = 300;
  GlTexture white(w, h, TexFormat::RGBA32F);
  white.upload(cv::Mat(h, w, CV_32FC3, cv::Scalar::all(1.0)));
  GlTarget dst(w, h, TexFormat::RGBA16F);
  EffectStackGl stack;
  StackParams p;
  p.vignette_radius_deg = 0;  // a cone of angle d around the axis: f = 1 - d / F peaks at d = 0
  p.vignette_falloff_deg = 60;  // reaches every corner of the view, unequally
  const struct {
    const char* name;
    Eigen::Vector2d centre_tan;
  } rows[] = {{"optical axis ahead", {0.0, 0.0}}, {"lens centre offset", {0.12, -0.08}}};
  for (const auto& r : rows) {
    RenderView eye;  // asymmetric like a real HMD eye: more FOV on the nasal side
    eye.tan_left = -1.3;
    eye.tan_right = 0.7;
    eye.tan_down = -1.0;
    eye.tan_up = 0.8;
    eye.optical_centre_tan = r.centre_tan;
    stack.apply(white, dst, p, effects::non_neutral_mask(p), eye);
    const cv::Mat img = test::bgr_clamped(dst.read_float());
    cv::Mat green;
    cv::extractChannel(img, green, 1);
    cv::Point peak;
    cv::minMaxLoc(green, nullptr, nullptr, nullptr, &peak);
    const Eigen::Vector2d found(peak.x + 0.5, peak.y + 0.5);
    const Eigen::Vector2d expected = eye.pixel_at(r.centre_tan, w, h);
    std::printf("[ vignette ] %s: peak pixel centre (%.1f, %.1f), projected optical centre "
                "(%.2f, %.2f), screen centre (%.0f, %.0f)\n",
                r.name, found.x(), found.y(), expected.x(), expected.y(), w / 2.0, h / 2.0);
    EXPECT_LE((found - expected).cwiseAbs().maxCoeff(), 0.5 + 1e-9) << r.name;
    EXPECT_GT((found - Eigen::Vector2d(w / 2.0, h / 2.0)).norm(), 20.0) << r.name;
    // Opposite corners at different distances from the centre get different darkening.
    EXPECT_NE(green.at<float>(0, 0), green.at<float>(h - 1, w - 1)) << r.name;
  }
}

}  // namespace
}  // namespace vdfx::xr
