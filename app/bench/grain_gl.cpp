/// @file
/// @brief Film grain knob of `vdfx bench`: one eye of the play frame with a grain layer of each
/// style (app/bench/grain_setup.h), timed interleaved with the same eye without it; for the
/// shader styles (headset plane, surface sphere) the GPU layer's error against the CPU reference
/// (effects::composite_shader_grain) over the bench eye's image. The volumetric styles have no
/// CPU reference: their rows give the time and say so.
#include "xr/grain_gl.h"

#include <epoxy/gl.h>

#include <stdexcept>

#include "app/bench/gl_rows.h"
#include "app/bench/grain_setup.h"
#include "effects/grain_render.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "grain";
constexpr double kIntensity = 0.5;

/// The style's one layer for `head`, at a fixed display time (one refresh).
effects::GrainFrame grain_frame(effects::GrainStyle style, const effects::HeadPose& head) {
  effects::GrainSet set = grain_set(style, kIntensity);
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
              row.note = "20000 particles";
              return;
            }
            double mean = 0.0, amplitude = 0.0;
            row.error = grain_error(ctx, style, &mean, &amplitude);
            row.add("mean_error", mean);
            row.add("grain_rms_steps", amplitude);
          });
  }
}

}  // namespace vdfx::app::bench
