/// @file
/// @brief RBF interpolation speed: evaluation, the whole stack, incremental add, full solve, and
/// local interpolation at film scale (N keyframes over 20 minutes at 30 fps: solve, evaluation,
/// an editor's add).
#include <benchmark/benchmark.h>

#include "app/bench/inputs.h"
#include "effects/keyframe_set.h"
#include "effects/rbf_interpolator.h"
#include "effects/stack_interpolator.h"

namespace vdfx::effects {
namespace {

using app::bench::random_keyframes;

void BM_RbfEvaluateOneEffect(benchmark::State& state) {
  const RbfInterpolator rbf(random_keyframes(static_cast<int>(state.range(0)), 1, 1), 1, {}, 30.0);
  const Eigen::Vector3d n = to_unit(Direction{12.0, 5.0});
  double out = 0;
  std::int64_t frame = 100;
  for (auto _ : state) {
    rbf.evaluate_into(n, frame++, &out);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_RbfEvaluateOneEffect)->Arg(1000);

void BM_RbfEvaluateStackSixEffects(benchmark::State& state) {
  std::vector<EffectTrack> tracks;
  for (int e = 0; e < kEffectCount; ++e) {
    EffectTrack t;
    t.type = static_cast<EffectType>(e);
    t.keyframes = random_keyframes(1000, effect_spec(t.type).dimension(), 10 + e);
    tracks.push_back(std::move(t));
  }
  const StackInterpolator s(tracks, {}, 30.0);
  std::int64_t frame = 100;
  for (auto _ : state) benchmark::DoNotOptimize(s.evaluate(Direction{12.0, 5.0}, frame++));
}
BENCHMARK(BM_RbfEvaluateStackSixEffects)->Unit(benchmark::kMicrosecond);

void BM_RbfIncrementalAdd(benchmark::State& state) {
  KeyframeSetOptions opt;
  opt.async = false;
  KeyframeSet set(1, {}, 30.0, random_keyframes(1000, 1, 2), opt);
  const auto extra = random_keyframes(4096, 1, 3);
  size_t i = 0;
  double full = 0;
  for (auto _ : state) {
    const auto e = set.add(extra[i % extra.size()]);
    state.PauseTiming();
    full += e.incremental ? 0 : 1;
    set.remove(set.keyframes().size() - 1);  // back to N = 1000 (untimed)
    ++i;
    state.ResumeTiming();
  }
  state.counters["full_solves"] = full;  // adds that fell back to a full solve (expect 0)
  // Edits (adds and the untimed removes) that ran a refinement step, per edit.
  const KeyframeSetStats st = set.stats();
  state.counters["refined"] =
      st.incremental_edits ? static_cast<double>(st.refinements) / st.incremental_edits : 0.0;
  state.counters["growths"] = static_cast<double>(st.storage_growths);
}
BENCHMARK(BM_RbfIncrementalAdd)->Unit(benchmark::kMillisecond);

void BM_RbfFullSolve(benchmark::State& state) {
  const auto k = random_keyframes(static_cast<int>(state.range(0)), 1, 4);
  for (auto _ : state) {
    const RbfInterpolator rbf(k, 1, {}, 30.0);
    benchmark::DoNotOptimize(rbf.diagnostics().max_residual);
  }
}
BENCHMARK(BM_RbfFullSolve)->Arg(100)->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);

constexpr std::int64_t kFilmFrames = 36000;

void BM_RbfFilmSolve(benchmark::State& state) {
  const auto k = random_keyframes(static_cast<int>(state.range(0)), 1, 5, kFilmFrames - 1);
  for (auto _ : state) {
    const RbfInterpolator rbf(k, 1, {}, 30.0);
    benchmark::DoNotOptimize(rbf.diagnostics().max_residual);
  }
}
BENCHMARK(BM_RbfFilmSolve)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_RbfFilmEvaluate(benchmark::State& state) {
  const RbfInterpolator rbf(
      random_keyframes(static_cast<int>(state.range(0)), 1, 6, kFilmFrames - 1), 1, {}, 30.0);
  const auto views = random_keyframes(1024, 1, 7, kFilmFrames - 1);
  double out = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Keyframe& v = views[i++ % views.size()];
    rbf.evaluate_into(to_unit(v.direction), v.frame, &out);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_RbfFilmEvaluate)->Arg(1000)->Arg(10000)->Arg(100000);

void BM_RbfFilmAdd(benchmark::State& state) {
  KeyframeSetOptions opt;
  opt.async = false;
  const auto n = static_cast<std::size_t>(state.range(0));
  KeyframeSet set(1, {}, 30.0, random_keyframes(static_cast<int>(n), 1, 8, kFilmFrames - 1), opt);
  const auto extra = random_keyframes(512, 1, 9, kFilmFrames - 1);
  std::size_t i = 0;
  for (auto _ : state) {
    set.add(extra[i++ % extra.size()]);
    state.PauseTiming();
    if (set.keyframes().size() > n) set.remove(set.keyframes().size() - 1);  // untimed
    state.ResumeTiming();
  }
  const KeyframeSetStats st = set.stats();
  state.counters["windows_per_edit"] =
      st.local_edits ? static_cast<double>(st.windows_solved) / st.local_edits : 0.0;
}
BENCHMARK(BM_RbfFilmAdd)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vdfx::effects
