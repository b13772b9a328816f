/// @file
/// @brief The editor's visualizations: the effect minimap (a coarse CPU grid, 128 x 64 RBF
/// evaluations by default) and the effect track (240 frames sampled at the view), for N = 10,
/// 100 and 1000 keyframes of one exposure effect on a 900-frame 30 fps clip. Peer in the same
/// run: one RBF evaluation (the unit both are made of).
///
/// The live preview (trigger placement or grab), per frame in which the preview keyframe moved:
/// the old path (a fresh RbfInterpolator of all keyframes, O(N^3)) against the pending edit's
/// interpolant (app/editor/pending_edit.h: one O(N^2) KeyframeSet::move), each followed by one
/// evaluation away from the view.
/// The preview's start (trigger press or grab) at N = 1000: the old seed, one full solve of the
/// keyframes and the pending keyframe (source 0, the peer), against the pending edit's seed,
/// cloning the document's solved set and one incremental add or move (source 1).
/// The frame thread while playing (a new frame every update) at N = 1000: the minimap computed
/// in update() (async 0) against handed to MinimapWorker (async 1); CPU time is the frame
/// thread's only.
///
/// At film scale (10000 and 100000 keyframes over 20 minutes): the preview's move per frame.
///
/// Report CPU-time medians (--benchmark_repetitions=N --benchmark_report_aggregates_only=true).
#include <benchmark/benchmark.h>

#include <random>

#include "app/editor/document.h"
#include "app/editor/editor.h"
#include "app/editor/visualizations.h"
#include "effects/keyframe_set.h"
#include "effects/rbf_interpolator.h"

namespace {

using vdfx::effects::Direction;
using vdfx::effects::EffectType;
using vdfx::effects::Keyframe;

constexpr std::int64_t kFrames = 900;

/// N exposure keyframes at uniformly random directions and frames (seeded: the same every run).
std::vector<Keyframe> make_keyframes(int n) {
  std::mt19937_64 rng(20240501u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> u(-1.0, 1.0), stops(-3.0, 3.0);
  std::uniform_int_distribution<std::int64_t> frame(0, kFrames - 1);
  std::vector<Keyframe> ks;
  for (int i = 0; i < n; ++i) {
    const double az = 180.0 * u(rng), alt = std::asin(u(rng)) * 180.0 / 3.14159265358979323846;
    ks.push_back({{az, alt}, frame(rng), {stops(rng)}});
  }
  return ks;
}

vdfx::effects::RbfInterpolator make_rbf(int n) {
  return vdfx::effects::RbfInterpolator(make_keyframes(n), 1, {}, 30.0);
}

/// The preview keyframe at step i: the head turning by 1.5 deg a frame.
Keyframe preview_key(int i) {
  return {{-60.0 + 1.5 * (i % 80), 5.0}, 450, {2.0}};
}

vdfx::io::Sidecar sidecar_of(std::vector<Keyframe> ks) {
  vdfx::io::Sidecar sc;
  sc.video = {"clip.mp4", 30.0, kFrames, 3840, 1920};
  sc.effects.push_back({EffectType::Exposure, std::nullopt, std::move(ks)});
  return sc;
}

/// Old path, the peer: a fresh interpolant of the keyframes and the preview keyframe.
void BM_EditorPreviewFresh(benchmark::State& state) {
  vdfx::app::Document doc(sidecar_of(make_keyframes(static_cast<int>(state.range(0)))),
                          {{.async = false}});
  auto& p = doc.begin_pending(EffectType::Exposure, std::nullopt, preview_key(0));
  int i = 0;
  for (auto _ : state) {
    p.set_key(preview_key(i++));
    const vdfx::effects::RbfInterpolator rbf(p.keyframe_list(), 1, {}, 30.0, {0.0});
    auto v = rbf.evaluate(Direction{100.0, 10.0}, 450);
    benchmark::DoNotOptimize(v.data());
  }
}
BENCHMARK(BM_EditorPreviewFresh)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

/// New path: seeded once (untimed), then one incremental move per frame.
void BM_EditorPreviewIncremental(benchmark::State& state) {
  vdfx::app::Document doc(sidecar_of(make_keyframes(static_cast<int>(state.range(0)))),
                          {{.async = false}});
  auto& p = doc.begin_pending(EffectType::Exposure, std::nullopt, preview_key(0));
  p.interpolant();
  int i = 1;
  for (auto _ : state) {
    p.set_key(preview_key(i++));
    auto v = p.interpolant()->evaluate(Direction{100.0, 10.0}, 450);
    benchmark::DoNotOptimize(v.data());
  }
  state.counters["seeds"] = static_cast<double>(doc.pending_stats().seeds);
}
BENCHMARK(BM_EditorPreviewIncremental)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

/// The same preview at film scale: N keyframes over 20 minutes (interpolated locally in time,
/// docs/interpolation.md), the playhead in the middle: each move re-solves the few windows the
/// preview keyframe lies in.
void BM_EditorPreviewFilm(benchmark::State& state) {
  constexpr std::int64_t film_frames = 36000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), stops(-3.0, 3.0);
  std::uniform_int_distribution<std::int64_t> frame(0, film_frames - 1);
  std::vector<Keyframe> ks;
  for (int i = 0; i < state.range(0); ++i)
    ks.push_back(
        {{180.0 * u(rng), std::asin(u(rng)) * 57.29577951308232}, frame(rng), {stops(rng)}});
  vdfx::io::Sidecar sc = sidecar_of(std::move(ks));
  sc.video.frames = film_frames;
  vdfx::app::Document doc(sc, {{.async = false}});
  const auto at = [](int i) {
    Keyframe k = preview_key(i);
    k.frame = 18000;
    return k;
  };
  auto& p = doc.begin_pending(EffectType::Exposure, std::nullopt, at(0));
  p.interpolant();
  int i = 1;
  for (auto _ : state) {
    p.set_key(at(i++));
    auto v = p.interpolant()->evaluate(Direction{100.0, 10.0}, 18000);
    benchmark::DoNotOptimize(v.data());
  }
}
BENCHMARK(BM_EditorPreviewFilm)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

/// The first interpolant of a preview (placement: grab 0; grab: grab 1): the peer (source 0)
/// solves the pending edit's keyframes from scratch; the pending edit (source 1) clones the
/// document's solved set. The pending edit is ended untimed.
void BM_EditorPreviewStart(benchmark::State& state) {
  vdfx::app::Document doc(sidecar_of(make_keyframes(static_cast<int>(state.range(0)))),
                          {{.async = false}});
  const bool grab = state.range(2) != 0;
  Keyframe held = doc.keyframes(EffectType::Exposure)[17];
  held.direction.azimuth_deg += 3.0;  // the first frame of the grab in which it moved
  int i = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto& p = doc.begin_pending(EffectType::Exposure,
                                grab ? std::optional<std::size_t>(17) : std::nullopt,
                                grab ? held : preview_key(i++));
    state.ResumeTiming();
    if (state.range(1) != 0) {
      auto v = p.interpolant()->evaluate(Direction{100.0, 10.0}, 450);
      benchmark::DoNotOptimize(v.data());
    } else {
      const vdfx::effects::KeyframeSet fresh(1, {}, 30.0, p.keyframe_list(), {.async = false},
                                             {0.0});
      auto v = fresh.solution()->evaluate(Direction{100.0, 10.0}, 450);
      benchmark::DoNotOptimize(v.data());
    }
    state.PauseTiming();
    doc.cancel_pending();
    state.ResumeTiming();
  }
  state.counters["full_seeds_per_start"] =
      static_cast<double>(doc.pending_stats().full_seeds) /
      static_cast<double>(std::max<std::uint64_t>(doc.pending_stats().seeds, 1));
}
BENCHMARK(BM_EditorPreviewStart)
    ->ArgNames({"n", "source", "grab"})
    ->Args({1000, 0, 0})
    ->Args({1000, 1, 0})
    ->Args({1000, 0, 1})
    ->Args({1000, 1, 1})
    ->Unit(benchmark::kMillisecond);

/// Editor::update while playing (head still): the frame thread's cost.
void BM_EditorPlayingFrame(benchmark::State& state) {
  vdfx::io::Sidecar sc;
  sc.video = {"clip.mp4", 30.0, kFrames, 3840, 1920};
  sc.effects.push_back(
      {EffectType::Exposure, std::nullopt, make_keyframes(static_cast<int>(state.range(0)))});
  vdfx::app::EditorOptions eo;
  eo.visuals.async = state.range(1) != 0;
  vdfx::app::Editor ed(sc, vdfx::app::DocumentOptions{{.async = false}}, eo);
  vdfx::xr::InputState in = vdfx::xr::neutral_input_state(0);
  in.head_tracked = true;
  std::int64_t t = 0;
  ed.update(in, t);
  ed.set_playing(true);
  for (auto _ : state) {
    t += 33'333'334;  // one video frame at 30 fps
    ed.update(in, t);
    benchmark::DoNotOptimize(ed.minimap_field().data);
  }
  state.counters["minimaps_shown"] = ed.minimap_computations();
}
BENCHMARK(BM_EditorPlayingFrame)->Args({1000, 0})->Args({1000, 1})->Unit(benchmark::kMillisecond);

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
