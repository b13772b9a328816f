/// @file
/// @brief What a flare costs per eye at generic90 (1440 x 1600, RGBA16F, 3840 x 1920 video, a
/// colour effect, mesh pre-distortion: the frame `vdfx play` renders), for each style, as a ratio
/// to the same eye without a flare measured in the same run (counter "x_frame"); the flare layer
/// alone against its ring count (counter "x_frame" too, and "ms_per_element"); and the CPU side
/// per frame: the layout (once per frame for both eyes) and the auto light's measurement of a
/// 3840 x 1920 frame.
///
/// Timing as in compositor_gl_bench.cpp: glFinish around each iteration, wall (manual) time, so
/// llvmpipe's CPU threads are what is measured. Run under `xvfb-run -a`.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "app/bench/flare_setup.h"
#include "effects/auto_light.h"
#include "effects/effect_shaders.h"
#include "effects/flare_layout.h"
#include "gl_bench_support.h"
#include "play_eye_fixture.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/session.h"
#include "xr/render/compositor.h"
#include "xr/render/flare_gl.h"
#include "xr/render/gl_context.h"
#include "xr/render/gpu_timer.h"

namespace {

using namespace vdfx;
using namespace vdfx::xr;

using bench::head_at;
using bench::synthetic_frame;

const effects::Direction kLook = app::bench::kFlareLook, kLight = app::bench::kFlareLight;

effects::FlareLayout layout(effects::FlareStyle style, int rings) {
  return app::bench::flare_layout(style, rings);
}

/// The play frame's left eye (bench::PlayEye) and the flare layer.
struct Fixture : bench::PlayEye {
  std::unique_ptr<FlareGl> flare;
  Fixture() : PlayEye(head_at(kLook)) {
    if (ctx) flare = std::make_unique<FlareGl>();
  }
};

Fixture& fixture() {
  static Fixture fx;
  return fx;
}

void run(benchmark::State& state, const std::function<void(Fixture&)>& body) {
  Fixture& f = fixture();
  if (!f.ctx) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  state.counters["x_frame"] = bench::timed_gl_loop(state, [&] { body(f); }) / f.frame_ms;
  state.counters["frame_ms"] = f.frame_ms;
}

/// One eye of the play frame with a flare (arg 1: directional, 2: headset, 6 rings each; 0: none),
/// interleaved with the same eye without it in every iteration so that the machine's load drifts
/// alike for both: counter "x_no_flare" = median with / median without.
void BM_GlFlareEye(benchmark::State& s) {
  const int which = static_cast<int>(s.range(0));
  Fixture& f = fixture();
  if (!f.ctx) {
    s.SkipWithError(f.error.c_str());
    return;
  }
  std::vector<effects::FlareLayout> flares;
  if (which == 1) flares = {layout(effects::FlareStyle::Directional, 6)};
  if (which == 2) flares = {layout(effects::FlareStyle::Headset, 6)};
  const std::array<EyeLayer*, 1> layers{f.flare.get()};
  const auto eye = [&](bool with) {
    f.flare->set_layouts(with ? flares : std::vector<effects::FlareLayout>{});
    return f.left_eye_ms(layers);
  };
  bench::interleaved_eye(s, eye, "x_no_flare");
}

/// The flare layer alone (into the eye buffer), directional style, against the ring count.
void BM_GlFlareLayerRings(benchmark::State& s) {
  const int rings = static_cast<int>(s.range(0));
  Fixture& f = fixture();
  if (f.flare) f.flare->set_layouts({layout(effects::FlareStyle::Directional, rings)});
  run(s, [](Fixture& fx) {
    fx.comp->eye_buffer(0).bind();
    fx.flare->draw(fx.eyes[0], 0, fx.comp->config().eye_width, fx.comp->config().eye_height);
  });
  s.counters["elements"] = 2 + rings;
}

/// CPU, once per frame: the layout of one flare from the head pose.
void BM_FlareLayout(benchmark::State& s) {
  const Pose h = head_at(kLook);
  const effects::HeadPose head{position_of(h), rotation_of(h)};
  const effects::FlareSettings settings;
  const Eigen::Vector3d l = effects::to_unit(kLight);
  for (auto _ : s)
    benchmark::DoNotOptimize(
        effects::layout_flare(effects::FlareStyle::Directional, settings, head, l, 1.0));
}

/// CPU, once per video frame with an auto light: the brightest-region measurement of a 3840 x
/// 1920 8-bit frame.
void BM_FlareAutoLightMeasure(benchmark::State& s) {
  const cv::Mat frame = synthetic_frame();
  for (auto _ : s) benchmark::DoNotOptimize(effects::find_brightest_region(frame));
  s.SetLabel("3840x1920 RGB8");
}

#define VDFX_GL_BENCH(fn) \
  BENCHMARK(fn)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(0.3)
VDFX_GL_BENCH(BM_GlFlareEye)->Arg(0)->Arg(1)->Arg(2)->MinTime(2.0);  // none, directional, headset
VDFX_GL_BENCH(BM_GlFlareLayerRings)->Arg(0)->Arg(2)->Arg(6)->Arg(12)->Arg(16);
BENCHMARK(BM_FlareLayout);
BENCHMARK(BM_FlareAutoLightMeasure)->Unit(benchmark::kMillisecond);

}  // namespace
