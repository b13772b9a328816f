/// @file
/// @brief The GPU effect stack against the CPU reference (effects/effect_stack.h, double).
#include "xr/render/effect_stack_gl.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "effects/coords.h"
#include "effects/effect_shaders.h"
#include "effects/effect_stack.h"
#include "effects/view_camera.h"
#include "gl_test_support.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {
namespace {

using effects::EffectType;
using effects::StackParams;
using test::GlTest;

// An asymmetric eye with an off-centre optical centre, so that geometry mistakes show.
// An asymmetric eye: the optical centre is off the image centre, so geometry mistakes show.
RenderView test_eye() {
  RenderView v;
  v.orientation = view_rotation({30, 10}, 0);
  v.tan_left = -1.1;
  v.tan_right = 0.9;
  v.tan_down = -0.8;
  v.tan_up = 0.7;
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

// The CPU reference (effects/effect_stack.h) sees the same eye through a pinhole camera with the
// same principal point: fx = W / (tan_right - tan_left), cx = -tan_left fx, cy = tan_up fy.
effects::ViewCamera camera_of(const RenderView& v, int w, int h) {
  const double fx = w / (v.tan_right - v.tan_left), fy = h / (v.tan_up - v.tan_down);
  return effects::ViewCamera(v.orientation, fx, fy, -v.tan_left * fx, v.tan_up * fy, w, h);
}

// effects::apply_stack works in RGB; the GL side reads back BGR.
cv::Mat reference_stack(const cv::Mat& src_bgr, const StackParams& p, const RenderView& v) {
  cv::Mat rgb, out;
  cv::cvtColor(src_bgr, rgb, cv::COLOR_BGR2RGB);
  cv::cvtColor(effects::apply_stack(rgb, p, camera_of(v, src_bgr.cols, src_bgr.rows)), out,
               cv::COLOR_RGB2BGR);
  cv::min(cv::max(out, 0.0), 1.0, out);
  return out;
}

const struct {
  const char* name;
  std::function<void(StackParams&)> set;
} kCases[] = {
    {"blur 1.5 deg", [](StackParams& p) { p.blur_sigma_deg = 1.5; }},
    {"blur 6 deg", [](StackParams& p) { p.blur_sigma_deg = 6.0; }},
    {"tint",
     [](StackParams& p) {
       p.set(EffectType::Tint, std::vector<double>{1.6, 0.8, 0.5});
     }},
    {"exposure +1.3", [](StackParams& p) { p.exposure_stops = 1.3; }},
    {"exposure -2", [](StackParams& p) { p.exposure_stops = -2.0; }},
    {"saturation 0.2", [](StackParams& p) { p.saturation = 0.2; }},
    {"saturation 2.5", [](StackParams& p) { p.saturation = 2.5; }},
    {"contrast 1.8", [](StackParams& p) { p.contrast = 1.8; }},
    {"contrast 0.4", [](StackParams& p) { p.contrast = 0.4; }},
    {"vignette 20/15",
     [](StackParams& p) {
       p.vignette_radius_deg = 20;
       p.vignette_falloff_deg = 15;
     }},
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
    const cv::Mat ref = reference_stack(src, p, eye);
    const test::ErrorStats e = test::compare(gpu, ref);
    std::printf("[ stack    ] %-16s max %.3f/255  mean %.4f/255\n", row.name, e.max * 255,
                e.mean * 255);
    EXPECT_LE(e.max, 2.0 / 255.0) << row.name;
    // The effect must have done something measurable, or the comparison proves nothing.
    EXPECT_GT(test::compare(ref, reference_stack(src, StackParams{}, eye)).mean, 1.0 / 255)
        << row.name;
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
  const std::string src_text =
      effects::stack_fragment_source(effects::shader_bit(EffectType::Contrast));
  EXPECT_NE(src_text.find("#define HAS_EXPOSURE 0"), std::string::npos);
}

TEST_F(EffectStackGlTest, VignetteIsCentredOnTheProjectedOpticalCentreOfAnOffCentreEye) {
  const int w = 400, h = 300;
  GlTexture white(w, h, TexFormat::RGBA32F);
  white.upload(cv::Mat(h, w, CV_32FC3, cv::Scalar::all(1.0)));
  GlTarget dst(w, h, TexFormat::RGBA16F);
  EffectStackGl stack;
  StackParams p;
  p.vignette_radius_deg = 0;    // a cone of angle d around the axis: f = 1 - d / F peaks at d = 0
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
    std::printf(
        "[ vignette ] %s: peak pixel centre (%.1f, %.1f), projected optical centre "
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
