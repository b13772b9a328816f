/// @file
/// @brief The editor's visualizations: the effect minimap (a coarse CPU grid, 128 x 64 RBF
/// evaluations by default) and the effect track (240 frames sampled at the view), for N = 10,
/// 100 and 1000 keyframes of one exposure effect on a 900-frame 30 fps clip. Peer in the same
/// run: one RBF evaluation (the unit both are made of).
///
/// Report CPU-time medians (--benchmark_repetitions=N --benchmark_report_aggregates_only=true).
#include <benchmark/benchmark.h>

#include <random>

#include "app/visualizations.h"
#include "effects/rbf_interpolator.h"

namespace {

using vdfx::effects::Direction;
using vdfx::effects::EffectType;
using vdfx::effects::Keyframe;

constexpr std::int64_t kFrames = 900;

/// N exposure keyframes at uniformly random directions and frames (seeded: the same every run).
vdfx::effects::RbfInterpolator make_rbf(int n) {
  std::mt19937_64 rng(20240501u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> u(-1.0, 1.0), stops(-3.0, 3.0);
  std::uniform_int_distribution<std::int64_t> frame(0, kFrames - 1);
  std::vector<Keyframe> ks;
  for (int i = 0; i < n; ++i) {
    const double az = 180.0 * u(rng), alt = std::asin(u(rng)) * 180.0 / 3.14159265358979323846;
    ks.push_back({{az, alt}, frame(rng), {stops(rng)}});
  }
  return vdfx::effects::RbfInterpolator(ks, 1, {}, 30.0);
}

void BM_EditorMinimap128x64(benchmark::State& state) {
  const auto rbf = make_rbf(static_cast<int>(state.range(0)));
  std::int64_t f = 0;
  for (auto _ : state) {
    f = (f + 1) % kFrames;  // what playback asks for: a new frame each time
    cv::Mat m = vdfx::app::effect_minimap(&rbf, EffectType::Exposure, f, 128, 64);
    benchmark::DoNotOptimize(m.data);
  }
  state.counters["evaluations"] = 128 * 64;
}
BENCHMARK(BM_EditorMinimap128x64)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_EditorTrack240(benchmark::State& state) {
  const auto rbf = make_rbf(static_cast<int>(state.range(0)));
  const auto frames = vdfx::app::track_sample_frames(kFrames, 240);
  double az = 0.0;
  for (auto _ : state) {
    az = az > 170.0 ? -170.0 : az + 1.5;  // the view turns by more than the 1-degree threshold
    auto v = vdfx::app::effect_track(&rbf, EffectType::Exposure, {az, 5.0}, frames);
    benchmark::DoNotOptimize(v.data());
  }
  state.counters["evaluations"] = static_cast<double>(frames.size());
}
BENCHMARK(BM_EditorTrack240)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// Peer: one evaluation, the unit of both figures above.
void BM_EditorRbfEvaluate(benchmark::State& state) {
  const auto rbf = make_rbf(static_cast<int>(state.range(0)));
  double az = 0.0;
  for (auto _ : state) {
    az = az > 170.0 ? -170.0 : az + 0.7;
    auto v = rbf.evaluate(Direction{az, 10.0}, 450);
    benchmark::DoNotOptimize(v.data());
  }
}
BENCHMARK(BM_EditorRbfEvaluate)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
