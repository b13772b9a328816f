/// @file
/// @brief VideoLayerGl: per-pixel ray into the mipmapped equirect texture.
#include "xr/render/video_layer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "effects/video_shaders.h"
#include "io/eye_picture.h"
#include "io/ycbcr.h"
#include "xr/render/gl_context.h"
#include "xr/render/gl_program.h"

namespace vdfx::xr {
namespace {

/// One Y'CbCr plane: a mipmapped one-channel texture (R8, or R16 for deeper video) wrapping in
/// u, reallocated only when its size or depth changes.
struct PlaneTexture {
  unsigned id = 0;
  int width = 0, height = 0;
  GLenum internal = 0;
  PlaneTexture() = default;
  PlaneTexture(const PlaneTexture&) = delete;
  PlaneTexture& operator=(const PlaneTexture&) = delete;
  ~PlaneTexture() {
    if (id) glDeleteTextures(1, &id);
  }
  /// Uploads `m` (CV_8UC1 or CV_16UC1; rows may be padded) as it is and rebuilds the mips;
  /// columns wrap (a 360 image) or are clamped (a VR180 image).
  void upload(const cv::Mat& m, bool wrap_u) {
    if (m.type() != CV_8UC1 && m.type() != CV_16UC1)
      throw GlError("VideoLayerGl: unsupported plane type " + std::to_string(m.type()));
    const bool deep = m.type() == CV_16UC1;
    const GLenum internal_fmt = deep ? GL_R16 : GL_R8;
    if (!id || width != m.cols || height != m.rows || internal != internal_fmt) {
      if (id) glDeleteTextures(1, &id);
      glGenTextures(1, &id);
      glBindTexture(GL_TEXTURE_2D, id);
      const int levels = full_mip_levels(m.cols, m.rows);
      glTexStorage2D(GL_TEXTURE_2D, levels, internal_fmt, m.cols, m.rows);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      width = m.cols;
      height = m.rows;
      internal = internal_fmt;
    }
    glBindTexture(GL_TEXTURE_2D, id);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_u ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(m.step[0] / m.elemSize()));
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m.cols, m.rows, GL_RED,
                    deep ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE, m.data);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glGenerateMipmap(GL_TEXTURE_2D);
    check_gl("VideoLayerGl plane upload");
  }
};

/// What one eye samples: its image as an RGB texture or as Y'CbCr planes.
struct EyeSource {
  GlTexture texture;  //!< RGB source (set_frame(cv::Mat), RGB pictures)
  int depth = -1;
  bool ycbcr = false;  //!< the planes below are the source
  std::array<PlaneTexture, 3> planes;
  io::YcbcrInfo info;
  float chroma_scale[2] = {1, 1}, chroma_offset[2] = {0, 0};
  bool has_frame() const { return ycbcr || static_cast<bool>(texture); }
  /// No frame (the plane textures stay allocated for the next one of their size).
  void clear() {
    texture = GlTexture();
    depth = -1;
    ycbcr = false;
  }
};

}  // namespace

struct VideoLayerGl::Impl {
  GlProgram program;
  unsigned vao = 0;
  effects::StereoLayout layout;
  std::array<EyeSource, 2> eyes;  //!< [0] only for mono video

  void set_rgb(EyeSource& e, const cv::Mat& equirect);
  void set_ycbcr(EyeSource& e, const io::Picture& pic);
  void bind_ycbcr(const GlProgram& p, const EyeSource& e);
};

VideoLayerGl::VideoLayerGl() : impl_(std::make_unique<Impl>()) {
  impl_->program = GlProgram::build("video_layer", fullscreen_vertex_source(),
                                    effects::video_layer_fragment_source());
  glGenVertexArrays(1, &impl_->vao);
}

VideoLayerGl::~VideoLayerGl() {
  if (impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
}

void VideoLayerGl::set_layout(const effects::StereoLayout& layout) {
  if (layout.coverage_deg != 360 && layout.coverage_deg != 180)
    throw GlError("VideoLayerGl::set_layout: coverage must be 360 or 180");
  impl_->layout = layout;
  for (EyeSource& e : impl_->eyes) e.clear();
}

const effects::StereoLayout& VideoLayerGl::layout() const {
  return impl_->layout;
}

void VideoLayerGl::Impl::set_rgb(EyeSource& e, const cv::Mat& equirect) {
  const int depth = equirect.depth();
  GlTexture& t = e.texture;
  if (!t || t.width() != equirect.cols || t.height() != equirect.rows || e.depth != depth) {
    const int levels = full_mip_levels(equirect.cols, equirect.rows);
    t = GlTexture(equirect.cols, equirect.rows,
                  depth == CV_8U ? TexFormat::RGBA8 : TexFormat::RGBA32F, levels);
    t.set_sampling(true, layout.coverage_deg == 360);
    e.depth = depth;
  }
  t.upload(equirect);
  t.generate_mipmaps();
  e.ycbcr = false;
}

void VideoLayerGl::set_frame(const cv::Mat& equirect) {
  if (equirect.empty()) throw GlError("VideoLayerGl::set_frame: empty frame");
  Impl& m = *impl_;
  if (effects::layout_problem(m.layout, equirect.cols, equirect.rows))
    throw GlError("VideoLayerGl::set_frame: the stereo layout does not divide the frame");
  const int n = m.layout.stereo() ? 2 : 1;
  for (int i = 0; i < n; ++i) {
    const effects::PixelRect r = effects::eye_rect(m.layout, static_cast<effects::EyeIndex>(i),
                                                   equirect.cols, equirect.rows);
    // A stereo half is copied into one continuous image (GlTexture uploads whole rows).
    const cv::Mat eye = n == 1 ? equirect : equirect(cv::Rect(r.x, r.y, r.width, r.height)).clone();
    m.set_rgb(m.eyes[static_cast<std::size_t>(i)], eye);
  }
}

void VideoLayerGl::Impl::set_ycbcr(EyeSource& e, const io::Picture& pic) {
  const bool wrap = layout.coverage_deg == 360;
  for (std::size_t i = 0; i < 3; ++i) e.planes[i].upload(pic.planes[i], wrap);
  e.info = pic.ycbcr;
  // Luma (u, v) -> chroma (u, v): pixel x = u W - 1/2 reads chroma sample (x - siting) / step,
  // at texture coordinate (that + 1/2) / chroma width (io/ycbcr.h's coordinate).
  const double size[2] = {static_cast<double>(pic.planes[0].cols),
                          static_cast<double>(pic.planes[0].rows)};
  const double chroma[2] = {static_cast<double>(pic.planes[1].cols),
                            static_cast<double>(pic.planes[1].rows)};
  const double step[2] = {std::ldexp(1.0, pic.ycbcr.log2_chroma_w),
                          std::ldexp(1.0, pic.ycbcr.log2_chroma_h)};
  const double siting[2] = {pic.ycbcr.chroma_x, pic.ycbcr.chroma_y};
  for (int a = 0; a < 2; ++a) {
    e.chroma_scale[a] = static_cast<float>(size[a] / (step[a] * chroma[a]));
    e.chroma_offset[a] = static_cast<float>((0.5 - (0.5 + siting[a]) / step[a]) / chroma[a]);
  }
  e.ycbcr = true;
}

void VideoLayerGl::set_frame(const io::Picture& pic) {
  if (pic.empty()) throw GlError("VideoLayerGl::set_frame: empty picture");
  Impl& m = *impl_;
  if (!pic.is_ycbcr()) {
    // Stills and RGB codecs: one channel swap into the RGB path (rare, and once for a still).
    cv::Mat bgr;
    cv::cvtColor(pic.rgb, bgr, cv::COLOR_RGB2BGR);
    set_frame(bgr);
    return;
  }
  if (!m.layout.stereo()) return m.set_ycbcr(m.eyes[0], pic);
  std::array<io::Picture, 2> halves;
  for (std::size_t i = 0; i < 2; ++i) {
    const effects::PixelRect r =
        effects::eye_rect(m.layout, static_cast<effects::EyeIndex>(i), pic.width(), pic.height());
    if (!io::cut_picture(pic, r, halves[i])) {
      // A half off the chroma grid (an odd half height in 4:2:0): converted on the CPU instead.
      cv::Mat bgr;
      cv::cvtColor(io::to_rgb(pic, io::PixelFormat::RgbF32), bgr, cv::COLOR_RGB2BGR);
      set_frame(bgr);
      return;
    }
  }
  for (std::size_t i = 0; i < 2; ++i) m.set_ycbcr(m.eyes[i], halves[i]);
}

void VideoLayerGl::Impl::bind_ycbcr(const GlProgram& p, const EyeSource& e) {
  for (int i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE1 + i);
    glBindTexture(GL_TEXTURE_2D, e.planes[static_cast<std::size_t>(i)].id);
    const std::string name = "u_plane" + std::to_string(i);
    glUniform1i(p.uniform(name.c_str()), 1 + i);
  }
  glActiveTexture(GL_TEXTURE0);
  const io::AffineMap3 a = io::ycbcr_to_rgb_map(e.info);
  float mat[9], off[3];
  for (std::size_t i = 0; i < 9; ++i) mat[i] = static_cast<float>(a.m[i]);
  for (std::size_t i = 0; i < 3; ++i) off[i] = static_cast<float>(a.offset[i]);
  glUniformMatrix3fv(p.uniform("u_m"), 1, GL_TRUE, mat);  // row-major in, GLSL is column-major
  glUniform3fv(p.uniform("u_offset"), 1, off);
  glUniform1f(p.uniform("u_code_scale"), e.planes[0].internal == GL_R16 ? 65535.0f : 255.0f);
  glUniform2f(p.uniform("u_chroma_scale"), e.chroma_scale[0], e.chroma_scale[1]);
  glUniform2f(p.uniform("u_chroma_offset"), e.chroma_offset[0], e.chroma_offset[1]);
}

void VideoLayerGl::render(const GlTarget& target, const RenderView& v, LodMode lod, int eye) {
  Impl& m = *impl_;
  target.bind();
  const EyeSource& e = m.eyes[m.layout.stereo() && eye == 1 ? 1 : 0];
  if (!e.has_frame()) {
    // No frame decoded yet (a video still loading): a dark, neutral field instead of a failure,
    // so the first frames of a window never depend on the decoder's head start.
    glClearColor(kNoFrameGrey, kNoFrameGrey, kNoFrameGrey, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  const GlProgram& p = impl_->program;
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, e.ycbcr ? 0 : e.texture.id());
  glUniform1i(p.uniform("u_equirect"), 0);
  glUniform1i(p.uniform("u_ycbcr"), e.ycbcr ? 1 : 0);
  if (e.ycbcr) m.bind_ycbcr(p, e);
  glUniform1f(p.uniform("u_coverage"), static_cast<float>(m.layout.coverage_deg));
  glUniform1f(p.uniform("u_edge"), static_cast<float>(effects::kCoverageEdgeDeg));
  glUniform4f(p.uniform("u_tan"), static_cast<float>(v.tan_left), static_cast<float>(v.tan_right),
              static_cast<float>(v.tan_down), static_cast<float>(v.tan_up));
  glUniform2f(p.uniform("u_size"), static_cast<float>(target.width()),
              static_cast<float>(target.height()));
  const Eigen::Matrix3f r = v.orientation.cast<float>();  // column-major, as GLSL expects
  glUniformMatrix3fv(p.uniform("u_rot"), 1, GL_FALSE, r.data());
  glUniform1i(p.uniform("u_lod_mode"), static_cast<int>(lod));
  glDisable(GL_BLEND);
  glBindVertexArray(impl_->vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

const GlTexture& VideoLayerGl::texture() const {
  return impl_->eyes[0].texture;
}
bool VideoLayerGl::has_frame() const {
  return impl_->eyes[0].has_frame();
}

}  // namespace vdfx::xr
