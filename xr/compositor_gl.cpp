/// @file
/// @brief Compositor: the per-eye pipeline, quad layers, mirror.
#include <epoxy/gl.h>

#include <array>

#include "xr/compositor.h"
#include "xr/effect_stack_gl.h"
#include "xr/gl_context.h"
#include "xr/gl_program.h"

namespace vdfx::xr {
namespace {

constexpr const char* kQuadVertex = R"(
uniform mat4 u_mvp;
out vec2 v_uv;
void main() {
  // Two triangles of a unit quad centred at the origin in its xy plane.
  const vec2 corners[6] = vec2[6](vec2(-0.5, -0.5), vec2(0.5, -0.5), vec2(0.5, 0.5),
                                  vec2(-0.5, -0.5), vec2(0.5, 0.5), vec2(-0.5, 0.5));
  vec2 c = corners[gl_VertexID];
  v_uv = c + 0.5;
  gl_Position = u_mvp * vec4(c, 0.0, 1.0);
}
)";

constexpr const char* kQuadFragment = R"(
in vec2 v_uv;
out vec4 frag;
uniform sampler2D u_tex;
void main() { frag = texture(u_tex, v_uv); }
)";

}  // namespace

struct Compositor::Impl {
  VideoLayerGl video;
  EffectStackGl stack;
  DistortionGl distortion;
  GlProgram quad_program;
  unsigned vao = 0;
  std::array<GlTarget, 2> video_out, eye_buffer, panel, seen;
  std::array<RenderView, 2> views;
  std::array<int, 2> margin{0, 0};  //!< pixels of video rendered around each eye's view
  GpuTimer timer;
  Impl(TexFormat f, BlurMethod b, double level_ratio) : stack(f, b) {
    stack.set_level_ratio(level_ratio);
  }
};

Compositor::Compositor(CompositorConfig config)
    : config_(std::move(config)), impl_(std::make_unique<Impl>(config_.eye_format, config_.blur,
                                                            config_.blur_level_ratio)) {
  const int w = config_.eye_width, h = config_.eye_height;
  for (int e = 0; e < 2; ++e) {
    impl_->video_out[e] = GlTarget(w, h, config_.eye_format);
    impl_->eye_buffer[e] = GlTarget(w, h, config_.eye_format);
    impl_->panel[e] = GlTarget(w, h, config_.eye_format);
  }
  impl_->quad_program = GlProgram::build("quad_layer", kQuadVertex, kQuadFragment);
  glGenVertexArrays(1, &impl_->vao);
}

Compositor::~Compositor() {
  if (impl_ && impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
}

void Compositor::set_video_frame(const cv::Mat& equirect) { impl_->video.set_frame(equirect); }
void Compositor::set_param_grid(const ParamGrid& grid) { impl_->stack.set_param_grid(grid); }

void Compositor::render_eye(int eye, const EyeInput& in, std::span<const QuadLayer> quads,
                            const Pose& head_in_local) {
  if (eye < 0 || eye > 1) throw GlError("Compositor::render_eye: eye must be 0 or 1");
  Impl& m = *impl_;
  const bool t = config_.gpu_timing;
  const std::string tag = eye == 0 ? "left " : "right ";
  m.views[eye] = in.view;
  // The video is rendered with a margin of the blur radius so the blur sees real image beyond the
  // view's border. The margin only grows while blur stays on (no reallocation per frame while
  // sigma is animated) and drops back to 0 when blur is off.
  const int w = config_.eye_width, h = config_.eye_height;
  effects::StackParams widest = in.params;  // per-pixel mode: the grid's largest sigma
  if (in.per_pixel) {
    if (!m.stack.has_param_grid())
      throw GlError("Compositor::render_eye: per-pixel eye without a parameter grid (set_param_grid)");
    widest.blur_sigma_deg = m.stack.grid_max_blur_sigma_deg();
  }
  const int need = blur_margin(widest, in.active_effects, in.view, w, h);
  int& margin = m.margin[eye];
  if (need == 0 || need > margin) {
    margin = need;
    if (m.video_out[eye].width() != w + 2 * margin)
      m.video_out[eye] = GlTarget(w + 2 * margin, h + 2 * margin, config_.eye_format);
  }
  if (t) m.timer.start(tag + "video");
  m.video.render(m.video_out[eye], with_margin(in.view, w, h, margin), config_.lod);
  if (t) m.timer.stop();
  if (t) m.timer.start(tag + "effects");
  if (in.per_pixel)
    m.stack.apply_per_pixel(m.video_out[eye].texture(), m.eye_buffer[eye], in.active_effects,
                            in.view, margin);
  else
    m.stack.apply(m.video_out[eye].texture(), m.eye_buffer[eye], in.params, in.active_effects,
                  in.view, margin);
  if (t) m.timer.stop();
  // World-space layers (flare, then grain): after the effects, before the UI quads.
  for (EyeLayer* layer : in.layers) {
    if (t) m.timer.start(tag + layer->name());
    m.eye_buffer[eye].bind();
    layer->draw(in.view, eye, w, h);
    if (t) m.timer.stop();
  }
  if (!quads.empty()) {
    if (t) m.timer.start(tag + "quads");
    m.eye_buffer[eye].bind();
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    m.quad_program.use();
    glBindVertexArray(m.vao);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(m.quad_program.uniform("u_tex"), 0);
    const Eigen::Matrix4d proj = in.view.projection(0.05, 100.0);
    const Eigen::Matrix4d view = in.view.world_to_eye();
    for (const QuadLayer& q : quads) {
      if (!q.texture) continue;
      const Pose p = Session::to_local(q.pose, q.space, head_in_local);
      Eigen::Matrix4d model = Eigen::Matrix4d::Identity();
      model.topLeftCorner<3, 3>() =
          rotation_of(p) * Eigen::Vector3d(q.size_m.x(), q.size_m.y(), 1.0).asDiagonal();
      model.topRightCorner<3, 1>() = position_of(p);
      const Eigen::Matrix4f mvp = (proj * view * model).cast<float>();
      glUniformMatrix4fv(m.quad_program.uniform("u_mvp"), 1, GL_FALSE, mvp.data());
      glBindTexture(GL_TEXTURE_2D, q.texture);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    glDisable(GL_BLEND);
    if (t) m.timer.stop();
  }
  if (t) m.timer.start(tag + "distortion");
  m.distortion.predistort(m.eye_buffer[eye].texture(), m.panel[eye], in.view, config_.lens,
                          config_.distortion);
  if (t) m.timer.stop();
}

void Compositor::draw_mirror(MirrorMode mode, const GlTarget* target, int width, int height) {
  Impl& m = *impl_;
  const unsigned dst_fbo = target ? target->fbo() : 0;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst_fbo);
  glViewport(0, 0, width, height);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const int ew = config_.eye_width, eh = config_.eye_height;
  const auto blit = [&](const GlTarget& src, int x0, int x1) {
    // Fit the eye image into columns [x0, x1) keeping its aspect ratio.
    const double s = std::min(static_cast<double>(x1 - x0) / ew, static_cast<double>(height) / eh);
    const int w = static_cast<int>(ew * s), h = static_cast<int>(eh * s);
    const int ox = x0 + (x1 - x0 - w) / 2, oy = (height - h) / 2;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src.fbo());
    glBlitFramebuffer(0, 0, ew, eh, ox, oy, ox + w, oy + h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  };
  if (mode == MirrorMode::SingleEye) {
    blit(m.eye_buffer[0], 0, width);
  } else {
    for (int e = 0; e < 2; ++e) {
      const GlTarget* src = &m.panel[e];
      if (mode == MirrorMode::ThroughTheLens) {
        if (!m.seen[e]) m.seen[e] = GlTarget(ew, eh, config_.eye_format);
        m.distortion.through_lens(m.panel[e].texture(), m.seen[e], m.views[e], config_.lens);
        src = &m.seen[e];
      }
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst_fbo);
      blit(*src, e * width / 2, (e + 1) * width / 2);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

cv::Mat Compositor::read_eye_buffer(int eye) const { return impl_->eye_buffer.at(eye).read_float(); }
cv::Mat Compositor::read_panel(int eye) const { return impl_->panel.at(eye).read_float(); }
const GlTarget& Compositor::eye_buffer(int eye) const { return impl_->eye_buffer.at(eye); }
const GlTarget& Compositor::panel(int eye) const { return impl_->panel.at(eye); }
std::vector<StageTime> Compositor::stage_times() { return impl_->timer.collect(); }

cv::Mat render_view_gpu(const cv::Mat& equirect, const RenderView& view, int width, int height,
                        const effects::StackParams& params, unsigned active_effects,
                        const GpuViewOptions& o) {
  CompositorConfig c;
  c.eye_width = width;
  c.eye_height = height;
  c.eye_format = TexFormat::RGBA32F;
  c.distortion = o.distortion;
  c.lens = o.lens;  // copied: LensModel is a value
  c.blur = o.blur;
  c.blur_level_ratio = o.blur_level_ratio;
  Compositor comp(c);
  comp.set_video_frame(equirect);
  if (o.param_grid) comp.set_param_grid(*o.param_grid);
  comp.render_eye(0, {view, params, active_effects, o.param_grid != nullptr, o.layers});
  return to_bgr8(comp.read_panel(0));
}

}  // namespace vdfx::xr
