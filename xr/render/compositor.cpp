/// @file
/// @brief Compositor: the per-eye pipeline, quad layers, mirror.
#include "xr/render/compositor.h"

#include <epoxy/gl.h>

#include <array>
#include <cmath>
#include <string>

#include "xr/render/effect_stack_gl.h"
#include "xr/render/gl_context.h"
#include "xr/render/gl_program.h"

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
  v_uv = vec2(c.x + 0.5, 0.5 - c.y);  // the texture's first row at the quad's top
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

/// Slots 0 and 1 are the eyes, slot 2 the desktop view.
constexpr int kDesktopSlot = 2;

struct Compositor::Impl {
  VideoLayerGl video;
  EffectStackGl stack;
  DistortionGl distortion;
  GlProgram quad_program;
  unsigned vao = 0;
  std::array<GlTarget, 3> video_out, eye_buffer;  //!< per slot: video (with margin), effects
  std::array<GlTarget, 2> display, seen;  //!< per eye: pre-distorted image, seen through lens
  GlTarget desktop;  //!< the desktop view at window size: scaled-up effects, then the quads
  std::array<RenderView, 3> views;
  std::array<int, 3> margin{0, 0, 0};  //!< pixels of video rendered around each slot's view
  int desktop_eye = 0;                 //!< the stereo video's eye the desktop view shows
  GpuTimer timer;
  Impl(TexFormat f, BlurMethod b, double level_ratio) : stack(f, b) {
    stack.set_level_ratio(level_ratio);
  }

  /// Video layer then effect stack of one slot into eye_buffer[slot] (w x h).
  void video_and_effects(int slot, const EyeInput& in, int w, int h, const CompositorConfig& c);
  /// Draws the quad layers into `target` with the view's projection.
  void quads(const GlTarget& target, const RenderView& view, std::span<const QuadLayer> layers,
             const Pose& head_in_local);
};

void Compositor::Impl::video_and_effects(int slot, const EyeInput& in, int w, int h,
                                         const CompositorConfig& c) {
  const bool t = c.gpu_timing;
  const std::string tag = slot == 0 ? "left " : slot == 1 ? "right " : "desktop ";
  views[slot] = in.view;
  if (eye_buffer[slot].width() != w || eye_buffer[slot].height() != h)
    eye_buffer[slot] = GlTarget(w, h, c.eye_format);
  // The video is rendered with a margin of the blur radius so the blur sees real image beyond the
  // view's border. The margin only grows while blur stays on (no reallocation per frame while
  // sigma is animated) and drops back to 0 when blur is off.
  effects::StackParams widest = in.params;  // per-pixel mode: the grid's largest sigma
  if (in.per_pixel) {
    if (!stack.has_param_grid())
      throw GlError(
          "Compositor::render_eye: per-pixel eye without a parameter grid (set_param_grid)");
    widest.blur_sigma_deg = stack.grid_max_blur_sigma_deg();
  }
  const int need = blur_margin(widest, in.active_effects, in.view, w, h);
  int& m = margin[slot];
  if (need == 0 || need > m) m = need;
  if (video_out[slot].width() != w + 2 * m || video_out[slot].height() != h + 2 * m)
    video_out[slot] = GlTarget(w + 2 * m, h + 2 * m, c.eye_format);
  if (t) timer.start(tag + "video");
  video.render(video_out[slot], with_margin(in.view, w, h, m), c.lod,
               slot == kDesktopSlot ? desktop_eye : slot);
  if (t) timer.stop();
  if (t) timer.start(tag + "effects");
  if (in.per_pixel)
    stack.apply_per_pixel(video_out[slot].texture(), eye_buffer[slot], in.active_effects, in.view,
                          m);
  else
    stack.apply(video_out[slot].texture(), eye_buffer[slot], in.params, in.active_effects, in.view,
                m);
  if (t) timer.stop();
  // World-space layers (flare, then grain): after the effects, before the UI quads. The desktop
  // view draws them as seen from the head (the cyclopean eye, index 0).
  for (EyeLayer* layer : in.layers) {
    if (t) timer.start(tag + layer->name());
    eye_buffer[slot].bind();
    layer->draw(in.view, slot == kDesktopSlot ? 0 : slot, w, h);
    if (t) timer.stop();
  }
}

void Compositor::Impl::quads(const GlTarget& target, const RenderView& view,
                             std::span<const QuadLayer> layers, const Pose& head_in_local) {
  if (layers.empty()) return;
  target.bind();
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over" (OpenXR's quad layers)
  quad_program.use();
  glBindVertexArray(vao);
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(quad_program.uniform("u_tex"), 0);
  const Eigen::Matrix4d proj = view.projection(0.05, 100.0);
  const Eigen::Matrix4d world_to_view = view.world_to_eye();
  for (const QuadLayer& q : layers) {
    if (!q.texture) continue;
    const Pose p = Session::to_local(q.pose, q.space, head_in_local);
    Eigen::Matrix4d model = Eigen::Matrix4d::Identity();
    model.topLeftCorner<3, 3>() =
        rotation_of(p) * Eigen::Vector3d(q.size_m.x(), q.size_m.y(), 1.0).asDiagonal();
    model.topRightCorner<3, 1>() = position_of(p);
    const Eigen::Matrix4f mvp = (proj * world_to_view * model).cast<float>();
    glUniformMatrix4fv(quad_program.uniform("u_mvp"), 1, GL_FALSE, mvp.data());
    glBindTexture(GL_TEXTURE_2D, q.texture);
    glDrawArrays(GL_TRIANGLES, 0, 6);
  }
  glDisable(GL_BLEND);
}

Compositor::Compositor(CompositorConfig config)
    : config_(std::move(config)),
      impl_(std::make_unique<Impl>(config_.eye_format, config_.blur, config_.blur_level_ratio)) {
  const int w = config_.eye_width, h = config_.eye_height;
  for (int e = 0; e < 2; ++e) {
    impl_->video_out[e] = GlTarget(w, h, config_.eye_format);
    impl_->eye_buffer[e] = GlTarget(w, h, config_.eye_format);
    impl_->display[e] = GlTarget(w, h, config_.eye_format);
  }
  impl_->quad_program = GlProgram::build("quad_layer", kQuadVertex, kQuadFragment);
  glGenVertexArrays(1, &impl_->vao);
}

Compositor::~Compositor() {
  if (impl_ && impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
}

void Compositor::set_video_layout(const effects::StereoLayout& layout) {
  impl_->video.set_layout(layout);
}

void Compositor::set_desktop_eye(int eye) {
  if (eye < 0 || eye > 1) throw GlError("Compositor::set_desktop_eye: eye must be 0 or 1");
  impl_->desktop_eye = eye;
}

void Compositor::set_video_frame(const cv::Mat& equirect) {
  impl_->video.set_frame(equirect);
}
void Compositor::set_video_frame(const io::Picture& picture) {
  impl_->video.set_frame(picture);
}
void Compositor::set_param_grid(const ParamGrid& grid) {
  impl_->stack.set_param_grid(grid);
}

void Compositor::render_eye(int eye, const EyeInput& in, std::span<const QuadLayer> quads,
                            const Pose& head_in_local) {
  if (eye < 0 || eye > 1) throw GlError("Compositor::render_eye: eye must be 0 or 1");
  Impl& m = *impl_;
  const bool t = config_.gpu_timing;
  const std::string tag = eye == 0 ? "left " : "right ";
  m.video_and_effects(eye, in, config_.eye_width, config_.eye_height, config_);
  if (!quads.empty()) {
    if (t) m.timer.start(tag + "quads");
    m.quads(m.eye_buffer[eye], in.view, quads, head_in_local);
    if (t) m.timer.stop();
  }
  if (t) m.timer.start(tag + "distortion");
  m.distortion.predistort(m.eye_buffer[eye].texture(), m.display[eye], in.view, config_.lens,
                          config_.distortion);
  if (t) m.timer.stop();
}

void Compositor::render_eye_buffer(int eye, const EyeInput& in) {
  if (eye < 0 || eye > 1) throw GlError("Compositor::render_eye_buffer: eye must be 0 or 1");
  impl_->video_and_effects(eye, in, config_.eye_width, config_.eye_height, config_);
}

void Compositor::draw_quads(int eye, std::span<const QuadLayer> quads, const Pose& head_in_local) {
  if (eye < 0 || eye > 1) throw GlError("Compositor::draw_quads: eye must be 0 or 1");
  impl_->quads(impl_->eye_buffer[eye], impl_->views[eye], quads, head_in_local);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Compositor::render_desktop(const EyeInput& in, int width, int height, double video_scale,
                                std::span<const QuadLayer> quads, const Pose& head_in_local) {
  if (width < 1 || height < 1 || !(video_scale > 0.0 && video_scale <= 1.0))
    throw GlError("Compositor::render_desktop: bad size " + std::to_string(width) + "x" +
                  std::to_string(height) + " or video scale " + std::to_string(video_scale));
  Impl& m = *impl_;
  const bool t = config_.gpu_timing;
  const int vw = std::max(8, static_cast<int>(std::lround(width * video_scale)));
  const int vh = std::max(8, static_cast<int>(std::lround(height * video_scale)));
  m.video_and_effects(kDesktopSlot, in, vw, vh, config_);
  if (m.desktop.width() != width || m.desktop.height() != height)
    m.desktop = GlTarget(width, height, config_.eye_format);
  if (t) m.timer.start("desktop quads");
  // The same tangents at both sizes: scaling the effects' image up keeps every ray in place.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.eye_buffer[kDesktopSlot].fbo());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m.desktop.fbo());
  glBlitFramebuffer(0, 0, vw, vh, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  m.quads(m.desktop, in.view, quads, head_in_local);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
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
  const auto blit = [&](const GlTarget& src, int sw, int sh, const WindowRect& r) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src.fbo());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst_fbo);
    const int y0 = height - (r.y + r.h);  // GL rows count from the bottom
    glBlitFramebuffer(0, 0, sw, sh, r.x, y0, r.x + r.w, y0 + r.h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  };
  if (mode == MirrorMode::Desktop) {
    if (m.desktop) blit(m.desktop, m.desktop.width(), m.desktop.height(), {0, 0, width, height});
  } else if (mode == MirrorMode::SingleEye) {
    blit(m.eye_buffer[0], ew, eh, mirror_eye_rect(mode, 0, ew, eh, width, height));
  } else {
    for (int e = 0; e < 2; ++e) {
      const GlTarget* src = &m.display[e];
      if (mode == MirrorMode::ThroughTheLens) {
        if (!m.seen[e]) m.seen[e] = GlTarget(ew, eh, config_.eye_format);
        m.distortion.through_lens(m.display[e].texture(), m.seen[e], m.views[e], config_.lens);
        src = &m.seen[e];
      }
      blit(*src, ew, eh, mirror_eye_rect(mode, e, ew, eh, width, height));
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

cv::Mat Compositor::read_desktop() const {
  return impl_->desktop.read_float();
}

cv::Mat Compositor::read_eye_buffer(int eye) const {
  return impl_->eye_buffer.at(eye).read_float();
}
cv::Mat Compositor::read_display(int eye) const {
  return impl_->display.at(eye).read_float();
}
const GlTarget& Compositor::eye_buffer(int eye) const {
  return impl_->eye_buffer.at(eye);
}
const GlTarget& Compositor::display(int eye) const {
  return impl_->display.at(eye);
}
std::vector<StageTime> Compositor::stage_times() {
  return impl_->timer.collect();
}

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
  comp.set_video_layout(o.layout);
  comp.set_video_frame(equirect);
  if (o.param_grid) comp.set_param_grid(*o.param_grid);
  const int eye = o.eye == 1 ? 1 : 0;
  comp.render_eye(eye, {view, params, active_effects, o.param_grid != nullptr, o.layers});
  return to_bgr8(comp.read_display(eye));
}

}  // namespace vdfx::xr
