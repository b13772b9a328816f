/// @file
/// @brief `vdfx suggest`'s knob of `vdfx bench` (docs/suggest.md, "Measured"): one exposure
/// suggestion over a generated clip of 10 s against its tolerance: the time, the keyframes it
/// places, and how far the interpolated field stays from its target. The peer is the same
/// suggestion with nothing to fit (a tolerance of 8 stops): the metering alone (decode of the
/// sampled frames, the luminance grids, the target field) and one error pass, so the ratio is
/// what the fit adds.
#include "app/suggest/suggest.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/bench/media.h"
#include "app/bench/registry.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "suggest.exposure";

suggest::SuggestReport suggest_once(const std::filesystem::path& clip, const io::VideoInfo& video,
                                    double tolerance) {
  suggest::SuggestRequest r;
  r.video = clip;
  r.tolerance = tolerance;
  io::Sidecar sidecar = io::new_sidecar(video);
  return suggest::suggest_into(r, sidecar);
}

}  // namespace

void add_suggest_knobs(Registry& r, bool quick) {
  r.knob({kKnob,
          "exposure suggestion (metering, greedy fit) of a generated 10 s clip against the "
          "tolerance T",
          "suggestion", "stops",
          "the target field at every sample (400 directions x the frames sampled, one a second)",
          "the same suggestion with nothing to fit (T = 8 stops): the metering alone",
          PlotError::Max, false, true});
  // 10 s: 4K at 30 fps; quick: a quarter of the width at 6 fps (60 frames).
  const int w = quick ? 960 : 3840, h = w / 2, fps = quick ? 6 : 30, frames = 10 * fps;
  const std::vector<double> tolerances =
      quick ? std::vector<double>{0.5, 0.1} : std::vector<double>{1.0, 0.5, 0.25, 0.1};
  for (const double t : tolerances) {
    char setting[32];
    std::snprintf(setting, sizeof setting, "T=%g", t);
    r.add(kKnob, setting, [=](Row& row, const Context& ctx) {
      const auto clip =
          media_clip("vdfx_bench_" + std::to_string(w) + "x" + std::to_string(h) + "_" +
                         std::to_string(frames) + "_" + std::to_string(fps) + "fps_h264.mp4",
                     w, h, frames, fps);
      Budget budget = ctx.budget;  // seconds a sample: a few samples only
      budget.min_samples = ctx.quick ? 1 : 3;
      budget.min_time_s = 0.0;
      const io::VideoInfo video{clip.string(), static_cast<double>(fps), frames, w, h};
      suggest::SuggestReport last;
      const auto times = measure_pair(Timed([&] { last = suggest_once(clip, video, t); }),
                                      Timed([&] { suggest_once(clip, video, 8.0); }), budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      const suggest::FitResult& fit = last.effects.at(0).fit;
      row.error.max = fit.max_error;
      row.error.rms = fit.rms_error;
      row.add("keyframes", static_cast<double>(fit.added.size()));
      row.add("samples", static_cast<double>(last.samples));
      row.add("within_tolerance", fit.within_tolerance ? 1.0 : 0.0);
      row.note = std::to_string(w) + "x" + std::to_string(h) + " H.264, " + std::to_string(frames) +
                 " frames at " + std::to_string(fps) + " fps; " +
                 std::to_string(last.frames.size()) + " frames metered; budget 256 keyframes";
    });
  }
}

}  // namespace vdfx::app::bench
