/// @file
/// @brief Film grain knob of `vdfx bench`: one eye of the play frame with a grain layer of each
/// style (app/bench/grain_setup.h), timed interleaved with the same eye without it; for the
/// shader styles (headset plane, surface sphere) the GPU layer's error against the CPU reference
/// (effects::composite_shader_grain) over the bench eye's image. The volumetric styles have no
/// CPU reference: their rows give the time and say so.
#include "xr/render/grain_gl.h"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

#include "app/bench/gl_rows.h"
#include "app/bench/grain_setup.h"
#include "effects/grain_particles.h"
#include "effects/grain_render.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "grain";
constexpr double kIntensity = 0.5;

constexpr const char* kRefreshKnob = "grain.refresh";
constexpr const char* kParticlesKnob = "grain.particles";

/// The style's one layer for `head`, at a fixed display time (one refresh); count 0: the style's
/// default.
effects::GrainFrame grain_frame(effects::GrainStyle style, const effects::HeadPose& head,
                                int count = 0, double sphere_m = 0.0) {
  effects::GrainSet set = grain_set(style, kIntensity, count, sphere_m);
  const auto frames = set.layout(head, 123'456'789, 0);
  if (frames.size() != 1) throw std::logic_error("the bench grain lays out no layer");
  return frames.front();
}

/// The layer drawn over the bench eye's image on the GPU against the CPU reference; the mean
/// error into *mean and, into *amplitude, the RMS change the grain makes to the image (so a
/// zero error is seen to compare something).
ErrorStats grain_error(const Context& ctx, effects::GrainStyle style, double* mean,
                       double* amplitude) {
  const BenchEye eye = bench_eye(ctx.quick);
  const effects::GrainFrame frame = grain_frame(style, {eye.view.position, eye.view.orientation});
  const cv::Mat& bg = eye_input_bgr(ctx.quick);
  xr::GlTarget target(eye.width, eye.height, xr::TexFormat::RGBA32F);
  target.texture().upload(bg);
  xr::GrainGl layer;
  layer.set_layers({frame});
  target.bind();
  layer.draw(eye.view, 0, eye.width, eye.height);
  cv::Mat cpu = bg.clone();
  effects::composite_shader_grain(cpu, frame, eye.view.orientation, eye.view.position,
                                  eye.view.tangents());
  const cv::Mat gpu = target.read_float();
  *amplitude = steps_error(gpu, bg).rms;
  return steps_error(gpu, cpu, mean);
}

std::string count_name(int count) {
  return "N=" + std::to_string(count);
}

/// CPU time of one refresh of an object cloud of `count` particles: the layout (parameters, the
/// refresh's key), a new refresh index every sample; beside it (peer) the CPU sampling of the same
/// particles that each refresh did when particles were made on the CPU
/// (effects::sample_grain_particles on the CPU threads, the definition the GPU now evaluates).
void refresh_row(Row& row, const Context& ctx, int count) {
  effects::GrainSet set = grain_set(effects::GrainStyle::ObjectCloud, kIntensity, count);
  const effects::GrainEffect& e = set.effect(0);
  const effects::HeadPose head = grain_head();
  std::int64_t t_ns = 0, refresh = 0;
  std::size_t layers = 0, sampled = 0;
  const PairTimes t = measure_pair({[&] {
                                     t_ns += 20'000'000;  // the next refresh
                                     layers += set.layout(head, t_ns, 0).size();
                                   }},
                                   {[&] {
                                     sampled += effects::sample_grain_particles(e.style, e.settings,
                                                                                e.seed, ++refresh)
                                                    .particles.size();
                                   }},
                                   ctx.budget);
  if (layers == 0 || sampled == 0) throw std::logic_error("the bench grain lays out nothing");
  row.time = t.subject;
  row.peer_time = t.peer;
  row.note = "object_cloud, default sphere; no particle is sampled on the CPU";
}

/// The layer alone (no eye image drawn) into one eye of the bench size, beside the plain copy of
/// that eye; the time per particle as an extra.
void particles_row(Row& row, const Context& ctx, effects::GrainStyle style, int count,
                   double sphere_m) {
  const BenchEye eye = bench_eye(ctx.quick);
  xr::GrainGl layer;
  layer.set_layers({grain_frame(style, grain_head(), count, sphere_m)});
  xr::GlTarget target(eye.width, eye.height, xr::TexFormat::RGBA16F);
  xr::RenderView view = eye.view;
  const effects::HeadPose head = grain_head();
  view.position = head.position;
  view.orientation = head.orientation;
  const PairTimes t = measure_pair(gl_timed([&] {
                                     target.bind();
                                     layer.draw(view, 0, eye.width, eye.height);
                                   }),
                                   copy_floor(ctx.quick), ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  row.add("per_particle_s", t.subject.median_s / count);
  row.note = std::string(effects::grain_style_name(style)) +
             (sphere_m > 0 ? ", sphere_m " + std::to_string(static_cast<int>(sphere_m)) : "") +
             ", default settings but the count";
}

void add_cost_knobs(Registry& r, bool quick) {
  r.knob({kRefreshKnob,
          "volumetric grain: CPU time of one refresh against the particle count (object_cloud)",
          "refresh", "-", "none: a time only",
          "the CPU sampling of the same particles (effects::sample_grain_particles, as before the "
          "GPU made them)",
          PlotError::Max, false, true});
  r.knob({kParticlesKnob,
          "volumetric grain: the layer alone into one eye, its particles generated on the GPU",
          "layer draw", "-",
          "none: a time only (GrainGlTest checks the particles against effects::grain_particle)",
          kCopyFloor, PlotError::Max, true, true});
  const std::vector<int> counts =
      quick ? std::vector<int>{10'000, 1'000'000} : std::vector<int>{10'000, 100'000, 1'000'000};
  for (const int n : counts)
    r.add(kRefreshKnob, count_name(n),
          [n](Row& row, const Context& ctx) { refresh_row(row, ctx, n); });
  // object_cloud at 10 m: the old default sphere, the one docs/grain.md's CPU-sampled figures
  // were taken at.
  struct Cloud {
    effects::GrainStyle style;
    double sphere_m;
    const char* name;
  };
  for (const Cloud c : {Cloud{effects::GrainStyle::ObjectCloud, 0.0, "object_cloud"},
                        Cloud{effects::GrainStyle::ObjectCloud, 10.0, "object_cloud 10 m"},
                        Cloud{effects::GrainStyle::FreeCloud, 0.0, "free_cloud"}})
    for (const int n : counts)
      r.add(kParticlesKnob, std::string(c.name) + " " + count_name(n),
            [c, n](Row& row, const Context& ctx) {
              particles_row(row, ctx, c.style, n, c.sphere_m);
            });
}

}  // namespace

void add_grain_knobs(Registry& r, bool quick) {
  r.knob({kKnob,
          "film grain per style (intensity 0.5, size 1, default settings) on one eye of the play "
          "frame",
          "eye", "8-bit steps", "CPU reference (effects::composite_shader_grain) on the bench eye",
          "the same eye without the grain (interleaved)", PlotError::Max, true, false});
  const std::vector<effects::GrainStyle> styles =
      quick ? std::vector<effects::GrainStyle>{effects::GrainStyle::Surface,
                                               effects::GrainStyle::ObjectCloud}
            : std::vector<effects::GrainStyle>(effects::kGrainStyles.begin(),
                                               effects::kGrainStyles.end());
  for (const effects::GrainStyle style : styles) {
    r.add(kKnob, std::string(effects::grain_style_name(style)),
          [style](Row& row, const Context& ctx) {
            xr::GrainGl layer;
            layer.set_layers({grain_frame(style, grain_head())});
            const PairTimes t = time_play_eye(ctx, layer);
            row.time = t.subject;
            row.peer_time = t.peer;
            if (effects::is_volumetric(style)) {
              row.reference = "none: the volumetric styles have no CPU reference";
              const effects::GrainSettings d(style);
              row.note = std::to_string(static_cast<int>(d.get(effects::GrainSetting::Count))) +
                         " particles (the style's defaults)";
              return;
            }
            double mean = 0.0, amplitude = 0.0;
            row.error = grain_error(ctx, style, &mean, &amplitude);
            row.add("mean_error", mean);
            row.add("grain_rms_steps", amplitude);
          });
  }
  add_cost_knobs(r, quick);
}

}  // namespace vdfx::app::bench
