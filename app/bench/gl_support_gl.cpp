/// @file
/// @brief The GL knobs' shared eye, input, copy floor, timing and error measure.
#include <epoxy/gl.h>

#include <array>
#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "app/bench/flare_setup.h"
#include "app/bench/gl_rows.h"
#include "app/bench/inputs.h"
#include "effects/effect_shaders.h"
#include "xr/headset/eye_views.h"
#include "xr/render/compositor.h"
#include "xr/render/effect_stack_gl.h"
#include "xr/render/video_layer.h"

namespace vdfx::app::bench {
namespace {

std::vector<std::function<void()>>& releases() {
  static std::vector<std::function<void()>> r;
  return r;
}

struct Input {
  xr::GlTexture texture;
  cv::Mat bgr;
  std::unique_ptr<xr::EffectStackGl> copier;
  xr::GlTarget copy_target;
};

std::map<bool, std::unique_ptr<Input>>& inputs() {
  static std::map<bool, std::unique_ptr<Input>>* m = [] {
    auto* p = new std::map<bool, std::unique_ptr<Input>>();
    on_gl_release([p] { p->clear(); });
    return p;
  }();
  return *m;
}

Input& input(bool quick) {
  auto& slot = inputs()[quick];
  if (slot) return *slot;
  slot = std::make_unique<Input>();
  const BenchEye eye = bench_eye(quick);
  xr::VideoLayerGl video;
  video.set_frame(synthetic_frame());
  xr::GlTarget target(eye.width, eye.height, xr::TexFormat::RGBA32F);
  video.render(target, eye.view);
  cv::Mat bgra = target.read_float();
  cv::cvtColor(bgra, slot->bgr, cv::COLOR_BGRA2BGR);
  slot->texture = xr::GlTexture(eye.width, eye.height, xr::TexFormat::RGBA32F);
  slot->texture.upload(slot->bgr);
  slot->copier = std::make_unique<xr::EffectStackGl>();
  slot->copy_target = xr::GlTarget(eye.width, eye.height, xr::TexFormat::RGBA16F);
  return *slot;
}

}  // namespace

void on_gl_release(std::function<void()> release) {
  releases().push_back(std::move(release));
}

void release_gl_caches() {
  for (auto& r : releases()) r();
}

Timed gl_timed(std::function<void()> work, double units) {
  return {[work = std::move(work)] {
            work();
            glFinish();
          },
          units};
}

BenchEye bench_eye(bool quick) {
  const effects::EyeLens& lens = generic90_left_lens();
  BenchEye e;
  e.view.orientation = xr::view_rotation({20.0, 10.0}, 0.0);
  e.view.tan_left = lens.fov.left;
  e.view.tan_right = lens.fov.right;
  e.view.tan_up = lens.fov.up;
  e.view.tan_down = lens.fov.down;
  e.width = quick ? lens.width / 2 : lens.width;
  e.height = quick ? lens.height / 2 : lens.height;
  return e;
}

const xr::GlTexture& eye_input(bool quick) {
  return input(quick).texture;
}
const cv::Mat& eye_input_bgr(bool quick) {
  return input(quick).bgr;
}

Timed copy_floor(bool quick) {
  Input& in = input(quick);
  const BenchEye eye = bench_eye(quick);
  return gl_timed([&in, eye] { in.copier->apply(in.texture, in.copy_target, {}, 0, eye.view); });
}

PairTimes time_play_eye(const Context& ctx, xr::EyeLayer& layer) {
  const xr::HmdProfile profile = xr::load_hmd_profile("generic90");
  const auto views = xr::locate_eye_views(head_at(kFlareLook), profile);
  xr::CompositorConfig c;
  c.eye_width = ctx.quick ? views[0].width / 2 : views[0].width;
  c.eye_height = ctx.quick ? views[0].height / 2 : views[0].height;
  c.lens = effects::LensModel(profile.lens);
  c.distortion.method = xr::DistortionMethod::Mesh;
  c.distortion.mesh_n = 65;
  xr::Compositor comp(c);
  comp.set_video_frame(synthetic_frame());
  effects::StackParams params;
  params.exposure_stops = 0.5;
  const unsigned mask = effects::non_neutral_mask(params);
  const xr::RenderView view = xr::render_view(views[0]);
  const std::array<xr::EyeLayer*, 1> with{&layer};
  return measure_pair(gl_timed([&] {
                        comp.render_eye(0, {view, params, mask, false, with});
                      }),
                      gl_timed([&] {
                        comp.render_eye(0, {view, params, mask, false, {}});
                      }),
                      ctx.budget);
}

}  // namespace vdfx::app::bench
