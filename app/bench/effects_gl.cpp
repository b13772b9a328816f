/// @file
/// @brief GL effect knobs of `vdfx bench`: each effect and the whole stack on the GPU against the
/// CPU reference in double (effects::apply_stack), and the GPU blur methods (exact separable and
/// pyramid) against the same reference; time per eye beside a plain textured copy of the eye.
#include <epoxy/gl.h>

#include <functional>
#include <map>
#include <opencv2/imgproc.hpp>

#include "app/bench/gl_rows.h"
#include "app/bench/inputs.h"
#include "app/bench/output.h"
#include "effects/effect_shaders.h"
#include "effects/effect_stack.h"
#include "effects/gaussian_blur.h"
#include "xr/render/effect_stack_gl.h"

namespace vdfx::app::bench {
namespace {

using effects::EffectType;
using effects::StackParams;

/// The CPU reference on the eye's input, BGR float like the GL readback; `seconds` its time.
cv::Mat cpu_reference(bool quick, const StackParams& p, double* seconds = nullptr) {
  const BenchEye eye = bench_eye(quick);
  cv::Mat rgb, out;
  cv::cvtColor(eye_input_bgr(quick), rgb, cv::COLOR_BGR2RGB);
  const double t0 = now_s();
  cv::Mat ref = effects::apply_stack(rgb, p, eye.view.camera(eye.width, eye.height));
  if (seconds) *seconds = now_s() - t0;
  cv::cvtColor(ref, out, cv::COLOR_RGB2BGR);
  return out;
}

/// Times the GL stack on the eye's input beside the copy floor and compares it with `ref`.
void stack_case(Row& row, const Context& ctx, const StackParams& p, xr::BlurMethod method,
                const cv::Mat& ref) {
  const BenchEye eye = bench_eye(ctx.quick);
  xr::EffectStackGl stack(xr::TexFormat::RGBA16F, method);
  const xr::GlTarget target(eye.width, eye.height, xr::TexFormat::RGBA16F);
  const unsigned mask = effects::non_neutral_mask(p);
  const xr::GlTexture& src = eye_input(ctx.quick);
  const auto t = measure_pair(gl_timed([&] { stack.apply(src, target, p, mask, eye.view); }),
                              copy_floor(ctx.quick), ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  stack.apply(src, target, p, mask, eye.view);
  double mean = 0.0;
  row.error = steps_error(target.read_float(), ref, &mean);
  row.add("mean_error", mean);
  row.note = std::to_string(eye.width) + "x" + std::to_string(eye.height) + " eye, RGBA16F";
}

struct EffectCase {
  const char* name;
  std::function<void(StackParams&)> set;
};

const std::vector<EffectCase>& effect_cases() {
  static const std::vector<EffectCase> cases = {
      {"blur 1 deg", [](StackParams& p) { p.blur_sigma_deg = 1.0; }},
      {"tint",
       [](StackParams& p) {
         p.set(EffectType::Tint, std::vector<double>{1.3, 1.0, 0.7});
       }},
      {"exposure +1", [](StackParams& p) { p.exposure_stops = 1.0; }},
      {"saturation 1.5", [](StackParams& p) { p.saturation = 1.5; }},
      {"contrast 1.3", [](StackParams& p) { p.contrast = 1.3; }},
      {"vignette 30/20",
       [](StackParams& p) {
         p.vignette_radius_deg = 30;
         p.vignette_falloff_deg = 20;
       }},
      {"full stack",
       [](StackParams& p) {
         p = colour_params();
         p.blur_sigma_deg = 1.0;
       }},
  };
  return cases;
}

/// The CPU reference of a blur-only stack, computed once per sigma (it is the slow part).
const cv::Mat& blur_reference(bool quick, double sigma_deg) {
  static std::map<std::pair<bool, double>, cv::Mat> cache;
  cv::Mat& ref = cache[{quick, sigma_deg}];
  if (ref.empty()) {
    StackParams p;
    p.blur_sigma_deg = sigma_deg;
    ref = cpu_reference(quick, p);
  }
  return ref;
}

/// OpenCV's GaussianBlur of the same eye image on the CPU (one thread), the blur peer of the
/// CPU knob, for scale: median of 3, once per sigma.
double opencv_blur_s(bool quick, double sigma_deg) {
  static std::map<std::pair<bool, double>, double> cache;
  auto it = cache.find({quick, sigma_deg});
  if (it != cache.end()) return it->second;
  const BenchEye eye = bench_eye(quick);
  const double fx = eye.width / (eye.view.tan_right - eye.view.tan_left);
  const double sigma = effects::sigma_px_from_deg(sigma_deg, fx);
  cv::Mat out;
  const TimeStats t = measure(
      {[&] { out = effects::blur_opencv(eye_input_bgr(quick), sigma, sigma); }}, {0.0, 3, 3});
  return cache[{quick, sigma_deg}] = t.median_s;
}

}  // namespace

void add_effects_gl_knobs(Registry& r, bool quick) {
  const std::string ref = "CPU reference in double (effects::apply_stack) on the same input";
  r.knob({"gl.effects",
          "each effect and the whole stack on the GPU (generic90 eye, synthetic 4K frame)", "eye",
          "8-bit steps", ref, kCopyFloor, PlotError::Max, true, false});
  for (const EffectCase& c : effect_cases()) {
    r.add("gl.effects", c.name, [set = c.set](Row& row, const Context& ctx) {
      StackParams p;
      set(p);
      double cpu_s = 0.0;
      const cv::Mat ref = cpu_reference(ctx.quick, p, &cpu_s);
      stack_case(row, ctx, p, xr::BlurMethod::Exact, ref);
      row.add("cpu_reference_s", cpu_s);
    });
  }

  r.knob({"blur.gl", "Gaussian blur on the GPU: exact separable against the pyramid", "eye",
          "8-bit steps", ref, kCopyFloor, PlotError::Max, true});
  const std::vector<double> sigmas =
      quick ? std::vector<double>{1, 4} : std::vector<double>{0.5, 1, 2, 4};
  for (const xr::BlurMethod m : {xr::BlurMethod::Exact, xr::BlurMethod::Pyramid}) {
    for (const double s : sigmas) {
      r.add("blur.gl", std::string(xr::blur_method_name(m)) + " " + setting_degrees(s),
            [m, s](Row& row, const Context& ctx) {
              StackParams p;
              p.blur_sigma_deg = s;
              stack_case(row, ctx, p, m, blur_reference(ctx.quick, s));
              row.series = setting_degrees(s);
              row.add("opencv_cpu_s", opencv_blur_s(ctx.quick, s));
            });
    }
  }
}

}  // namespace vdfx::app::bench
