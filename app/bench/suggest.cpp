/// @file
/// @brief `vdfx suggest`'s knobs of `vdfx bench` (docs/suggest.md, "Measured"). suggest.exposure:
/// one exposure suggestion over a generated clip of 10 s against its tolerance: the time, the
/// keyframes it places, and how far the interpolated field stays from its target. The peer is
/// the same suggestion with nothing to fit (a tolerance of 8 stops): the metering alone (decode
/// of the sampled frames, the luminance grids, the target field) and one error pass, so the
/// ratio is what the fit adds. suggest.fit: the greedy fit alone over a synthetic field of M
/// samples, its steps placing a share of the keyframes there, against the plain greedy fit (one
/// keyframe a step): the time and the keyframes of both.
#include "app/suggest/suggest.h"

#include <algorithm>
#include <cmath>
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

/// An exposure-like target over `directions` x `frames` samples: six soft bright and dark
/// patches (Gaussian in the angle, 15 to 40 degrees wide, up to 3 stops) drifting in azimuth by
/// 4 degrees a frame. A fixed formula: every run fits the same field.
suggest::TargetField drifting_patches(int directions, int frames) {
  suggest::TargetField field;
  const auto dirs = suggest::sphere_directions(directions);
  for (int f = 0; f < frames; ++f)
    for (const auto& d : dirs) {
      const Eigen::Vector3d u = effects::to_unit(d);
      double v = 0.0;
      for (int k = 0; k < 6; ++k) {
        const effects::Direction c{-150.0 + 60.0 * k + 4.0 * f, 40.0 * std::sin(1.3 * k)};
        const double theta = effects::angle_between(u, effects::to_unit(c));
        const double sigma = (15.0 + 5.0 * k) * effects::kDegToRad;
        v +=
            (k % 2 ? -1.0 : 1.0) * (1.0 + 0.4 * k) * std::exp(-theta * theta / (2 * sigma * sigma));
      }
      field.add(d, f, std::span(&v, 1));
    }
  return field;
}

/// The fit's options: one frame weighs like 30 degrees of view (fps 1), a budget of 4096.
suggest::FitOptions fit_options(double tolerance, double step_share) {
  suggest::FitOptions o;
  o.tolerance = tolerance;
  o.max_keyframes = 4096;
  o.fps = 1.0;
  o.settings.time_scale = effects::time_scale_from_deg_per_s(30.0);
  o.neutral = {0.0};
  o.step_share = step_share;
  return o;
}

void add_fit_knob(Registry& r, bool quick) {
  r.knob({"suggest.fit",
          "the greedy fit alone over M samples (directions x frames) of a synthetic field "
          "against the tolerance T, with steps that place a share of the keyframes there",
          "fit", "stops", "the target field at every sample",
          "the plain greedy fit: one keyframe a step, the field measured after each",
          PlotError::Max, false, false});
  struct Setting {
    int directions, frames;
    double tolerance;
  };
  const std::vector<Setting> settings =
      quick ? std::vector<Setting>{{400, 2, 0.1}}
            : std::vector<Setting>{
                  {400, 1, 0.05}, {2000, 1, 0.02}, {2000, 4, 0.05}, {2000, 10, 0.05}};
  for (const Setting& s : settings) {
    char name[48];
    std::snprintf(name, sizeof name, "M=%dx%d T=%g", s.directions, s.frames, s.tolerance);
    r.add("suggest.fit", name, [s](Row& row, const Context& ctx) {
      const suggest::TargetField field = drifting_patches(s.directions, s.frames);
      const suggest::FitOptions steps = fit_options(s.tolerance, suggest::FitOptions{}.step_share);
      const suggest::FitOptions single = fit_options(s.tolerance, 0.0);
      Budget budget = ctx.budget;  // seconds a sample: a few samples only
      budget.min_samples = ctx.quick ? 1 : 3;
      budget.min_time_s = 0.0;
      suggest::FitResult fit, plain;
      const auto times =
          measure_pair(Timed([&] { fit = suggest::fit_greedy(field, steps); }),
                       Timed([&] { plain = suggest::fit_greedy(field, single); }), budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      row.error.max = fit.max_error;
      row.error.rms = fit.rms_error;
      row.add("keyframes", static_cast<double>(fit.added.size()));
      row.add("peer_keyframes", static_cast<double>(plain.added.size()));
      row.add("peer_error_max", plain.max_error);
      row.add("steps", static_cast<double>(fit.steps));
      row.add("within_tolerance", fit.within_tolerance ? 1.0 : 0.0);
      row.note = std::to_string(field.size()) + " samples; step share " +
                 std::to_string(steps.step_share).substr(0, 5) + "; budget 4096 keyframes";
    });
  }
}

}  // namespace

void add_suggest_knobs(Registry& r, bool quick) {
  add_fit_knob(r, quick);
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
