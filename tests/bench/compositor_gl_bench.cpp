/// @file
/// @brief Per-eye GPU time of each compositor stage at 1440 x 1600 (video layer, effect stack,
/// pre-distortion pixel vs mesh N, through-the-lens), with a plain textured copy of the same size
/// measured in the same run as the memory-bound floor (counter "x_copy" = time / copy time), and
/// the blur methods (exact separable vs pyramid) at sigma 0.5, 1, 2, 4 degrees, with the pyramid's
/// time as a ratio to the exact blur measured in the same run (counter "x_exact") and its error
/// against it (counters "max_err", "mean_err", 0..1 units).
///
/// Timing: every iteration ends with glFinish, and the benchmark uses real time, so a stage's
/// time is the wall time of its GPU work (llvmpipe runs it on the CPU threads). Needs a display
/// (run under `xvfb-run -a`); without one every case reports the context error.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "app/bench/inputs.h"
#include "effects/effect_shaders.h"
#include "gl_bench_support.h"
#include "xr/render/distortion_gl.h"
#include "xr/render/effect_stack_gl.h"
#include "xr/render/gl_context.h"
#include "xr/render/gpu_timer.h"
#include "xr/render/video_layer.h"

namespace {

using namespace vdfx;
using namespace vdfx::xr;

constexpr int kW = 1440, kH = 1600;

struct Fixture {
  std::unique_ptr<GlContext> ctx;
  std::string error;
  std::unique_ptr<VideoLayerGl> video;
  std::unique_ptr<EffectStackGl> stack;
  std::unique_ptr<DistortionGl> distortion;
  GlTarget a, b;
  RenderView eye;
  effects::LensModel lens;
  double copy_ms = 0.0;
};

Fixture& fixture() {
  static Fixture fx = [] {
    Fixture f;
    try {
      f.ctx = GlContext::create();
    } catch (const GlError& e) {
      f.error = e.what();
      return f;
    }
    f.video = std::make_unique<VideoLayerGl>();
    f.video->set_frame(app::bench::synthetic_frame());  // 3840 x 1920, a common 4K 360 size
    f.stack = std::make_unique<EffectStackGl>();
    f.distortion = std::make_unique<DistortionGl>();
    f.a = GlTarget(kW, kH, TexFormat::RGBA16F);
    f.b = GlTarget(kW, kH, TexFormat::RGBA16F);
    // An eye like generic90's: about 100 x 104 degrees, asymmetric horizontally.
    f.eye = RenderView::look_at({20, 10}, 0, 100, kW, kH);
    f.eye.tan_left = -1.30;
    f.eye.tan_right = 1.08;
    effects::LensParams lp;
    lp.c1 = 0.22;
    lp.c2 = 0.24;
    lp.lca_scale = {0.985, 1.0, 1.015};
    f.lens = effects::LensModel(lp);
    f.video->render(f.a, f.eye);
    // The memory-bound floor: the stack's copy pass (an empty mask), median of 7.
    f.copy_ms = bench::median_wall_ms(7, [&] { f.stack->apply(f.a.texture(), f.b, {}, 0, f.eye); });
    return f;
  }();
  return fx;
}

void run(benchmark::State& state, const std::function<void(Fixture&)>& body) {
  Fixture& f = fixture();
  if (!f.ctx) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  const double mean_ms = bench::timed_gl_loop(state, [&] { body(f); });
  state.counters["x_copy"] = mean_ms / f.copy_ms;
  state.counters["copy_ms"] = f.copy_ms;
}

void BM_GlCopyFloor(benchmark::State& s) {
  run(s, [](Fixture& f) { f.stack->apply(f.a.texture(), f.b, {}, 0, f.eye); });
}
void BM_GlVideoLayer(benchmark::State& s) {
  const auto lod = static_cast<LodMode>(s.range(0));
  run(s, [lod](Fixture& f) { f.video->render(f.a, f.eye, lod); });
}
void BM_GlColourEffects(benchmark::State& s) {
  const effects::StackParams p = app::bench::colour_params();
  run(s, [p](Fixture& f) {
    f.stack->apply(f.a.texture(), f.b, p, effects::non_neutral_mask(p), f.eye);
  });
}
void BM_GlFullStackBlurSigmaCentiDeg(benchmark::State& s) {
  effects::StackParams p;
  p.blur_sigma_deg = static_cast<double>(s.range(0)) / 100.0;
  p.exposure_stops = 0.5;
  p.saturation = 1.3;
  p.contrast = 1.2;
  p.vignette_radius_deg = 30;
  p.vignette_falloff_deg = 20;
  run(s, [p](Fixture& f) {
    f.stack->apply(f.a.texture(), f.b, p, effects::non_neutral_mask(p), f.eye);
  });
}
// Blur alone (no other effect), the given method; x_exact against the exact blur of the same
// sigma timed once (median of 3) in this run.
void BM_GlBlurMethodSigmaCentiDeg(benchmark::State& s) {
  const auto method = static_cast<BlurMethod>(s.range(0));
  effects::StackParams p;
  p.blur_sigma_deg = static_cast<double>(s.range(1)) / 100.0;
  const unsigned mask = effects::non_neutral_mask(p);
  static std::map<long, std::pair<double, cv::Mat>> exact;  // sigma -> (median ms, image)
  static std::unique_ptr<EffectStackGl> exact_stack, pyramid_stack;
  Fixture& fx = fixture();
  if (fx.ctx && !exact.count(s.range(1))) {
    if (!exact_stack)
      exact_stack = std::make_unique<EffectStackGl>(TexFormat::RGBA16F, BlurMethod::Exact);
    std::vector<double> t;
    for (int i = 0; i < 3; ++i)
      t.push_back(
          finished_wall_ms([&] { exact_stack->apply(fx.a.texture(), fx.b, p, mask, fx.eye); }));
    std::sort(t.begin(), t.end());
    exact[s.range(1)] = {t[1], fx.b.read_float()};
  }
  if (fx.ctx && !pyramid_stack)
    pyramid_stack = std::make_unique<EffectStackGl>(TexFormat::RGBA16F, BlurMethod::Pyramid);
  EffectStackGl* stack = method == BlurMethod::Exact ? exact_stack.get() : pyramid_stack.get();
  run(s, [&](Fixture& f) { stack->apply(f.a.texture(), f.b, p, mask, f.eye); });
  if (!fx.ctx) return;
  const auto& [exact_ms, exact_img] = exact[s.range(1)];
  cv::Mat d, rgb;
  cv::absdiff(fx.b.read_float(), exact_img, d);
  double mx = 0.0;
  cv::Scalar mean = cv::mean(d);
  for (int c = 0; c < 3; ++c) {
    cv::extractChannel(d, rgb, c);
    double m = 0.0;
    cv::minMaxLoc(rgb, nullptr, &m);
    mx = std::max(mx, m);
  }
  s.counters["exact_ms"] = exact_ms;
  // run() left the mean time as x_copy * copy_ms.
  s.counters["x_exact"] = s.counters["x_copy"] * s.counters["copy_ms"] / exact_ms;
  s.counters["max_err"] = mx;
  s.counters["mean_err"] = (mean[0] + mean[1] + mean[2]) / 3.0;
}
void BM_GlPredistortPixel(benchmark::State& s) {
  const int iters = static_cast<int>(s.range(0));
  run(s, [iters](Fixture& f) {
    f.distortion->predistort(f.a.texture(), f.b, f.eye, f.lens,
                             {DistortionMethod::Pixel, 0, iters, true, false});
  });
}
void BM_GlPredistortMesh(benchmark::State& s) {
  const int n = static_cast<int>(s.range(0));
  run(s, [n](Fixture& f) {
    f.distortion->predistort(f.a.texture(), f.b, f.eye, f.lens,
                             {DistortionMethod::Mesh, n, 0, true, false});
  });
}
void BM_GlThroughLens(benchmark::State& s) {
  run(s, [](Fixture& f) { f.distortion->through_lens(f.a.texture(), f.b, f.eye, f.lens); });
}

#define VDFX_GL_BENCH(fn) \
  BENCHMARK(fn)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(0.3)
VDFX_GL_BENCH(BM_GlCopyFloor);
VDFX_GL_BENCH(BM_GlVideoLayer)->Arg(0)->Arg(1)->Arg(2);  // LodMode analytic, derivatives, base
VDFX_GL_BENCH(BM_GlColourEffects);
VDFX_GL_BENCH(BM_GlFullStackBlurSigmaCentiDeg)->Arg(50)->Arg(100)->Arg(200);
VDFX_GL_BENCH(BM_GlBlurMethodSigmaCentiDeg)
    ->ArgsProduct({{0, 1}, {50, 100, 200, 400}})
    ->ArgNames({"pyramid", "sigma_cdeg"});  // 0 exact, 1 pyramid
VDFX_GL_BENCH(BM_GlPredistortPixel)->Arg(4)->Arg(8);
VDFX_GL_BENCH(BM_GlPredistortMesh)->Arg(5)->Arg(9)->Arg(17)->Arg(33)->Arg(65);
VDFX_GL_BENCH(BM_GlThroughLens);

}  // namespace
