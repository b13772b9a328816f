/// @file
/// @brief What film grain costs per eye at generic90 (bench::PlayEye: the frame `vdfx play`
/// renders), for each style, as a ratio to the same eye without grain measured in the same run
/// and interleaved with it (counter "x_no_grain" = median with / median without); a grain at
/// intensity 0 (no layer: the ratio should be 1); the particle count (1k, 10k, 100k, 1M) against
/// the layer's draw cost per eye, and a refresh's CPU sampling and upload.
///
/// Timing as in compositor_gl_bench.cpp: glFinish around each iteration, wall (manual) time, so
/// llvmpipe's CPU threads are what is measured. Run under
/// `xvfb-run -a ./build/vdfx_bench --benchmark_filter=Grain`.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <array>
#include <chrono>
#include <memory>
#include <vector>

#include "app/bench/flare_setup.h"
#include "app/bench/grain_setup.h"
#include "effects/grain_layout.h"
#include "gl_bench_support.h"
#include "play_eye_fixture.h"
#include "xr/render/grain_gl.h"

namespace {

using namespace vdfx;
using namespace vdfx::xr;

using app::bench::grain_set;

/// The play frame's left eye looking where the flare benchmarks look, and the grain layer.
struct Fixture : bench::PlayEye {
  std::unique_ptr<GrainGl> grain;
  effects::HeadPose head = app::bench::grain_head();
  Fixture() : PlayEye(bench::head_at(app::bench::kFlareLook)) {
    if (ctx) grain = std::make_unique<GrainGl>();
  }
};

Fixture& fixture() {
  static Fixture fx;
  return fx;
}

/// One eye of the play frame with a grain layer (arg 0: style 0 headset, 1 surface, 2
/// object_cloud, 3 free_cloud, the style's default settings; arg 1: intensity in percent,
/// 0 = no layer), interleaved with the same eye without grain in every iteration.
void BM_GlGrainEye(benchmark::State& s) {
  Fixture& f = fixture();
  if (!f.ctx) {
    s.SkipWithError(f.error.c_str());
    return;
  }
  effects::GrainSet set = grain_set(effects::kGrainStyles[static_cast<std::size_t>(s.range(0))],
                                    static_cast<double>(s.range(1)) / 100.0);
  const std::vector<effects::GrainFrame> layers = set.layout(f.head, 0, 0);
  const std::array<EyeLayer*, 1> eye_layers{f.grain.get()};
  const auto eye = [&](bool with) {
    f.grain->set_layers(with ? layers : std::vector<effects::GrainFrame>{});
    return f.left_eye_ms(eye_layers);
  };
  bench::interleaved_eye(s, eye, "x_no_grain");
  s.counters["layers"] = static_cast<double>(layers.size());
}

/// The grain layer alone (into the eye buffer), particles generated in the vertex stage: count
/// against cost.
void BM_GlGrainParticlesDraw(benchmark::State& s) {
  Fixture& f = fixture();
  if (!f.ctx) {
    s.SkipWithError(f.error.c_str());
    return;
  }
  const auto style = s.range(0) ? effects::GrainStyle::FreeCloud : effects::GrainStyle::ObjectCloud;
  // object_cloud at 10 m, the sphere docs/grain.md's CPU-particle figures were taken at.
  effects::GrainSet set = grain_set(style, 0.5, static_cast<int>(s.range(1)),
                                    style == effects::GrainStyle::ObjectCloud ? 10.0 : 0.0);
  f.grain->set_layers(set.layout(f.head, 0, 0));
  const double ms = bench::timed_gl_loop(s, [&] {
    f.comp->eye_buffer(0).bind();
    f.grain->draw(f.eyes[0], 0, f.width(), f.height());
  });
  s.counters["x_frame"] = ms / f.frame_ms;
  s.counters["frame_ms"] = f.frame_ms;
}

/// Every iteration a new refresh: the layout on the CPU (counter "sample_ms": the refresh's key,
/// no particle sampled since issue 24), then the draw into one eye.
void BM_GlGrainParticlesRefresh(benchmark::State& s) {
  Fixture& f = fixture();
  if (!f.ctx) {
    s.SkipWithError(f.error.c_str());
    return;
  }
  effects::GrainSet set =
      grain_set(effects::GrainStyle::ObjectCloud, 0.5, static_cast<int>(s.range(0)));
  std::int64_t refresh = 0;
  double sample_ms = 0.0;
  const double ms = bench::timed_gl_loop(s, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    f.grain->set_layers(set.layout(f.head, 20'000'000 * refresh++, 0));
    sample_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    f.comp->eye_buffer(0).bind();
    f.grain->draw(f.eyes[0], 0, f.width(), f.height());
  });
  s.counters["sample_ms"] = sample_ms / static_cast<double>(refresh);
  s.counters["x_frame"] = ms / f.frame_ms;
}

#define VDFX_GL_BENCH(fn) \
  BENCHMARK(fn)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(0.3)
VDFX_GL_BENCH(BM_GlGrainEye)
    ->ArgsProduct({{0, 1, 2, 3}, {50}})
    ->Args({1, 0})
    ->ArgNames({"style", "intensity_pct"})
    ->MinTime(2.0);
VDFX_GL_BENCH(BM_GlGrainParticlesDraw)
    ->ArgsProduct({{0, 1}, {1000, 10000, 100000, 1000000}})
    ->ArgNames({"free_cloud", "count"});
VDFX_GL_BENCH(BM_GlGrainParticlesRefresh)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->ArgName("count");

}  // namespace
