/// @file
/// @brief Flare knob of `vdfx bench`: one eye of the play frame (generic90, exposure, mesh
/// pre-distortion) with a flare of each style, timed interleaved with the same eye without it;
/// the error of the GPU flare layer against the CPU reference (effects::add_flares) drawn alone.
#include "xr/render/flare_gl.h"

#include <epoxy/gl.h>

#include <array>
#include <opencv2/imgproc.hpp>

#include "app/bench/flare_setup.h"
#include "app/bench/gl_rows.h"
#include "app/bench/inputs.h"
#include "effects/flare_render.h"
#include "xr/headset/eye_views.h"
#include "xr/render/compositor.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "flare";

struct Eye {
  xr::RenderView view;
  int width = 0, height = 0;
};

Eye left_eye(bool quick) {
  const xr::HmdProfile profile = xr::load_hmd_profile("generic90");
  const auto views = xr::locate_eye_views(head_at(kFlareLook), profile);
  Eye e;
  e.view = xr::render_view(views[0]);
  e.width = quick ? views[0].width / 2 : views[0].width;
  e.height = quick ? views[0].height / 2 : views[0].height;
  return e;
}

/// The flare alone (black video, no distortion, float eye buffer) against the CPU reference.
ErrorStats flare_error(const Context& ctx, const effects::FlareLayout& flare, double* mean) {
  const Eye eye = left_eye(ctx.quick);
  xr::CompositorConfig c;
  c.eye_width = eye.width;
  c.eye_height = eye.height;
  c.eye_format = xr::TexFormat::RGBA32F;
  c.distortion.method = xr::DistortionMethod::None;
  xr::Compositor comp(c);
  comp.set_video_frame(cv::Mat(32, 64, CV_32FC3, cv::Scalar::all(0)));
  xr::FlareGl layer;
  layer.set_layouts({flare});
  const std::array<xr::EyeLayer*, 1> layers{&layer};
  comp.render_eye(0, {eye.view, {}, 0, false, layers});
  cv::Mat cpu(eye.height, eye.width, CV_32FC3, cv::Scalar::all(0)), cpu_bgr;
  const std::array<effects::FlareLayout, 1> flares{flare};
  effects::add_flares(cpu, eye.view.camera(eye.width, eye.height), eye.view.position, flares);
  cv::cvtColor(cpu, cpu_bgr, cv::COLOR_RGB2BGR);
  return steps_error(comp.read_eye_buffer(0), cpu_bgr, mean);
}

}  // namespace

void add_flare_knobs(Registry& r, bool quick) {
  r.knob({kKnob, "lens flare per style on one eye of the play frame (generic90, exposure, mesh 65)",
          "eye", "8-bit steps", "CPU reference (effects::add_flares) of the flare alone",
          "the same eye without the flare (interleaved)", PlotError::Max, true, false});
  struct Setting {
    effects::FlareStyle style;
    int rings;
  };
  const std::vector<Setting> settings =
      quick ? std::vector<Setting>{{effects::FlareStyle::Directional, 6},
                                   {effects::FlareStyle::Headset, 6}}
            : std::vector<Setting>{{effects::FlareStyle::Directional, 0},
                                   {effects::FlareStyle::Directional, 6},
                                   {effects::FlareStyle::Directional, 16},
                                   {effects::FlareStyle::Headset, 6}};
  for (const Setting& s : settings) {
    r.add(
        kKnob,
        std::string(effects::flare_style_name(s.style)) + ", " + std::to_string(s.rings) + " rings",
        [s](Row& row, const Context& ctx) {
          const effects::FlareLayout flare = flare_layout(s.style, s.rings);
          xr::FlareGl layer;
          layer.set_layouts({flare});
          const PairTimes t = time_play_eye(ctx, layer);
          row.time = t.subject;
          row.peer_time = t.peer;
          double mean = 0.0;
          row.error = flare_error(ctx, flare, &mean);
          row.add("mean_error", mean);
          const Eye eye = left_eye(ctx.quick);
          row.note = std::to_string(eye.width) + "x" + std::to_string(eye.height) + " eye";
        });
  }
}

}  // namespace vdfx::app::bench
