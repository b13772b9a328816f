/// @file
/// @brief Film grain cost per eye at 1440 x 1600 (generic90's eye): each style's layer as a ratio
/// to the whole eye frame without grain (video layer, colour effects, mesh pre-distortion)
/// measured in the same run (counter "x_frame"); a zero-intensity grain (no layer: must cost
/// nothing); particle count 1k, 10k, 100k, 1M against the draw cost per eye, the CPU sampling of
/// one refresh and its upload.
///
/// Timing as in compositor_gl_bench.cpp: glFinish around every iteration, wall (manual) time.
/// Run under `xvfb-run -a ./build/vdfx_bench --benchmark_filter=Grain`.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/effect_shaders.h"
#include "effects/grain_layout.h"
#include "xr/compositor.h"
#include "xr/gl_context.h"
#include "xr/gpu_timer.h"
#include "xr/grain_gl.h"

namespace {

using namespace vdfx;
using namespace vdfx::xr;

constexpr int kW = 1440, kH = 1600;

struct Fixture {
  std::unique_ptr<GlContext> ctx;
  std::string error;
  std::unique_ptr<Compositor> compositor;
  std::unique_ptr<GrainGl> grain;
  RenderView eye;
  effects::StackParams params;
  unsigned mask = 0;
  double frame_ms = 0.0;

  void frame(std::span<EyeLayer* const> layers) {
    compositor->render_eye(0, {eye, params, mask, false, layers});
  }
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
    CompositorConfig c;
    c.eye_width = kW;
    c.eye_height = kH;
    effects::LensParams lp;
    lp.c1 = 0.22;
    lp.c2 = 0.24;
    lp.lca_scale = {0.985, 1.0, 1.015};
    c.lens = effects::LensModel(lp);
    f.compositor = std::make_unique<Compositor>(c);
    // A 3840 x 1920 frame (a common 4K 360 video size), the compositor benchmark's pattern.
    cv::Mat frame(1920, 3840, CV_8UC3);
    frame.forEach<cv::Vec3b>([](cv::Vec3b& p, const int* pos) {
      p = cv::Vec3b(static_cast<uchar>((pos[1] * 7) & 255), static_cast<uchar>((pos[0] * 3) & 255),
                    static_cast<uchar>(((pos[0] + pos[1]) / 4) & 255));
    });
    f.compositor->set_video_frame(frame);
    f.grain = std::make_unique<GrainGl>();
    // generic90's left eye, head at the origin looking at (20, 10).
    f.eye = RenderView::from_angles(view_rotation({20, 10}, 0), -52 * effects::kDegToRad,
                                    47 * effects::kDegToRad, -53 * effects::kDegToRad,
                                    53 * effects::kDegToRad);
    f.eye.position = f.eye.orientation * Eigen::Vector3d(-0.0315, 0, 0);
    f.params.exposure_stops = 0.3;
    f.params.saturation = 1.2;
    f.params.vignette_radius_deg = 40;
    f.params.vignette_falloff_deg = 20;
    f.mask = effects::non_neutral_mask(f.params);
    // The peer: the same frame without grain, median of 7.
    f.frame({});
    std::vector<double> t;
    for (int i = 0; i < 7; ++i) t.push_back(finished_wall_ms([&] { f.frame({}); }));
    std::nth_element(t.begin(), t.begin() + 3, t.end());
    f.frame_ms = t[3];
    return f;
  }();
  return fx;
}

effects::GrainSet grain_set(effects::GrainStyle style, double intensity, int count) {
  effects::GrainEffect e;
  e.style = style;
  e.seed = 7;
  e.settings.set(effects::GrainSetting::Count, count);
  e.keyframes = {{{0, 0}, 0, {intensity, 1.0}}};
  return effects::GrainSet({e}, {}, 30.0);
}

/// Times `body` per iteration; x_frame = mean / the frame without grain.
void run(benchmark::State& state, const std::function<void(Fixture&)>& body) {
  Fixture& f = fixture();
  if (!f.ctx) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  body(f);  // warm-up: compiles, uploads
  glFinish();
  double total = 0.0;
  for (auto _ : state) {
    const double ms = finished_wall_ms([&] { body(f); });
    state.SetIterationTime(ms * 1e-3);
    total += ms;
  }
  state.counters["x_frame"] = total / static_cast<double>(state.iterations()) / f.frame_ms;
  state.counters["frame_ms"] = f.frame_ms;
}

// The whole eye frame without grain (the peer, timed by the benchmark loop too).
void BM_GrainFrameWithout(benchmark::State& s) {
  run(s, [](Fixture& f) { f.frame({}); });
}

// The whole eye frame with one grain layer of a style (0 headset, 1 surface, 2 object_cloud,
// 3 free_cloud; default settings, 20000 particles), intensity in percent.
void BM_GrainFrameWithStyle(benchmark::State& s) {
  const auto style = effects::kGrainStyles[static_cast<std::size_t>(s.range(0))];
  effects::GrainSet set = grain_set(style, s.range(1) / 100.0, 20000);
  Fixture& fx = fixture();
  if (fx.ctx) fx.grain->set_layers(set.layout({}, 0, 0));
  run(s, [](Fixture& f) {
    const std::array<EyeLayer*, 1> layers{f.grain.get()};
    f.frame(layers);
  });
}

// The grain layer alone (drawn over the eye buffer), particles already uploaded: count vs cost.
void BM_GrainParticleDrawCount(benchmark::State& s) {
  const auto style = s.range(0) ? effects::GrainStyle::FreeCloud : effects::GrainStyle::ObjectCloud;
  effects::GrainSet set = grain_set(style, 0.5, static_cast<int>(s.range(1)));
  Fixture& fx = fixture();
  if (fx.ctx) {
    fx.grain->set_layers(set.layout({}, 0, 0));
    fx.frame({});
  }
  run(s, [](Fixture& f) {
    f.compositor->eye_buffer(0).bind();
    f.grain->draw(f.eye, 0, kW, kH);
  });
}

// One refresh's new particles: CPU sampling (counter "sample_ms") plus the upload and draw.
void BM_GrainParticleRefreshCount(benchmark::State& s) {
  effects::GrainSet set = grain_set(effects::GrainStyle::ObjectCloud, 0.5, static_cast<int>(s.range(0)));
  std::int64_t refresh = 0;
  double sample_ms = 0.0;
  run(s, [&](Fixture& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f.grain->set_layers(set.layout({}, 20'000'000 * refresh++, 0));
    sample_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    f.compositor->eye_buffer(0).bind();
    f.grain->draw(f.eye, 0, kW, kH);
  });
  s.counters["sample_ms"] = sample_ms / static_cast<double>(refresh);
}

#define VDFX_GL_BENCH(fn) \
  BENCHMARK(fn)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(0.3)
VDFX_GL_BENCH(BM_GrainFrameWithout);
VDFX_GL_BENCH(BM_GrainFrameWithStyle)
    ->ArgsProduct({{0, 1, 2, 3}, {50}})
    ->Args({1, 0})  // intensity 0: no layer
    ->ArgNames({"style", "intensity_pct"});
VDFX_GL_BENCH(BM_GrainParticleDrawCount)
    ->ArgsProduct({{0, 1}, {1000, 10000, 100000, 1000000}})
    ->ArgNames({"free_cloud", "count"});
VDFX_GL_BENCH(BM_GrainParticleRefreshCount)->Arg(1000)->Arg(10000)->Arg(100000)->ArgName("count");

}  // namespace
