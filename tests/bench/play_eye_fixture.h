/// @file
/// @brief The frame `vdfx play` renders for one eye at generic90 (1440 x 1600, RGBA16F, a 3840 x
/// 1920 video, one colour effect, mesh pre-distortion), shared by the benchmarks of the layers
/// drawn into it (flare, grain), and the synthetic video frame the GL benchmarks use.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "app/bench/inputs.h"
#include "effects/effect_shaders.h"
#include "gl_bench_support.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/session.h"
#include "xr/render/compositor.h"
#include "xr/render/gl_context.h"

namespace vdfx::bench {

// The inputs `vdfx bench` uses too (app/bench/inputs.h).
using app::bench::head_at;
using app::bench::synthetic_frame;

struct PlayEye {
  std::unique_ptr<xr::GlContext> ctx;
  std::string error;  //!< why there is no context
  std::unique_ptr<xr::Compositor> comp;
  std::array<xr::RenderView, 2> eyes;
  effects::StackParams params;
  unsigned mask = 0;
  double frame_ms = 0.0;  //!< the left eye with no layer, median of 7

  /// Needs a display; without one `ctx` stays empty and `error` says why.
  explicit PlayEye(const xr::Pose& head) {
    try {
      ctx = xr::GlContext::create();
    } catch (const xr::GlError& e) {
      error = e.what();
      return;
    }
    const xr::HmdProfile profile = xr::load_hmd_profile("generic90");
    xr::CompositorConfig c;
    c.eye_width = profile.eye(xr::Eye::Left).width;
    c.eye_height = profile.eye(xr::Eye::Left).height;
    c.lens = effects::LensModel(profile.lens);
    c.distortion.method = xr::DistortionMethod::Mesh;
    c.distortion.mesh_n = 65;
    comp = std::make_unique<xr::Compositor>(c);
    comp->set_video_frame(synthetic_frame());
    const auto views = xr::locate_eye_views(head, profile);
    for (std::size_t e = 0; e < 2; ++e) eyes[e] = xr::render_view(views[e]);
    params.exposure_stops = 0.5;
    mask = effects::non_neutral_mask(params);
    const auto eye = [&] { comp->render_eye(0, {eyes[0], params, mask}); };
    eye();  // compiles the shaders
    frame_ms = median_wall_ms(7, eye);
  }

  /// The left eye with these layers, wall ms.
  double left_eye_ms(std::span<xr::EyeLayer* const> layers) {
    return xr::finished_wall_ms([&] {
      comp->render_eye(0, {eyes[0], params, mask, false, layers});
    });
  }
  int width() const { return comp->config().eye_width; }
  int height() const { return comp->config().eye_height; }
};

/// Times `eye(true)` (with the layer) against `eye(false)` (without) alternately in every
/// iteration, so that the machine's load drifts alike for both; the manual time is the eye with
/// the layer. Counters: without_ms, and `ratio` = median with / median without.
inline void interleaved_eye(benchmark::State& s, const std::function<double(bool)>& eye,
                            const std::string& ratio) {
  eye(true);  // compiles, uploads
  std::vector<double> with, without;
  for (auto _ : s) {
    without.push_back(eye(false));
    with.push_back(eye(true));
    s.SetIterationTime(with.back() * 1e-3);
  }
  s.counters["without_ms"] = median(without);
  s.counters[ratio] = median(with) / median(without);
}

}  // namespace vdfx::bench
