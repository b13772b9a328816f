/// @file
/// @brief VideoLayerGl: per-pixel ray into the mipmapped equirect texture.
#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "io/ycbcr.h"
#include "xr/gl_context.h"
#include "xr/gl_program.h"
#include "xr/video_layer.h"

namespace vdfx::xr {
namespace {

constexpr const char* kFragment = R"(out vec4 frag;
uniform sampler2D u_equirect;
uniform vec4 u_tan;      // left, right, down, up tangents
uniform vec2 u_size;     // target size in pixels
uniform mat3 u_rot;      // eye -> world
uniform int u_lod_mode;  // 0 analytic, 1 hardware derivatives, 2 base level
const float PI = 3.14159265358979;

vec2 ray_uv(vec3 d) {
  // t = 1 - v: the texture's origin is the bottom row (gl_texture.h).
  return vec2(0.5 + atan(d.x, -d.z) / (2.0 * PI), 0.5 + atan(d.y, length(d.xz)) / PI);
}

// (du, dv) for a change e of the (unnormalised) ray d; see video_layer.h for the formulas.
vec2 uv_differential(vec3 d, vec3 e) {
  float h2 = max(dot(d.xz, d.xz), 1e-12);
  float h = sqrt(h2);
  float daz = (-d.z * e.x + d.x * e.z) / h2;
  float dh = (d.x * e.x + d.z * e.z) / h;
  float dalt = (h * e.y - d.y * dh) / (h2 + d.y * d.y);
  return vec2(daz / (2.0 * PI), dalt / PI);
}

void main() {
  vec2 q = gl_FragCoord.xy / u_size;
  vec3 d = u_rot * vec3(mix(u_tan.x, u_tan.y, q.x), mix(u_tan.z, u_tan.w, q.y), -1.0);
  vec2 uv = ray_uv(d);
  vec4 c;
  if (u_lod_mode == 0) {
    vec3 ex = u_rot[0] * ((u_tan.y - u_tan.x) / u_size.x);
    vec3 ey = u_rot[1] * ((u_tan.w - u_tan.z) / u_size.y);
    c = textureGrad(u_equirect, uv, uv_differential(d, ex), uv_differential(d, ey));
  } else if (u_lod_mode == 1) {
    vec2 gx = dFdx(uv), gy = dFdy(uv);
    float u2 = fract(uv.x + 0.5);  // jumps at azimuth 0 instead of at the seam
    float gx2 = dFdx(u2), gy2 = dFdy(u2);
    if (abs(gx2) < abs(gx.x)) gx.x = gx2;
    if (abs(gy2) < abs(gy.x)) gy.x = gy2;
    c = textureGrad(u_equirect, uv, gx, gy);
  } else {
    c = textureLod(u_equirect, uv, 0.0);
  }
  frag = vec4(c.rgb, 1.0);
}
)";

// Decoded picture -> level 0 of the equirect texture. Planes were uploaded top row first, so
// image row = H - 1 - the fragment's row. Chroma is read with texelFetch and blended with the
// CPU reference's own weights (io/ycbcr.cpp), not the sampler's lower-precision filtering.
constexpr const char* kConvertFragment = R"(out vec4 frag;
uniform sampler2D u_plane0, u_plane1, u_plane2;
uniform int u_rgb;           // 1: plane 0 is packed RGB, copied as is
uniform ivec2 u_size;        // luma size
uniform ivec2 u_chroma_size;
uniform vec2 u_chroma_step;  // 2^log2_chroma_w, 2^log2_chroma_h
uniform vec2 u_siting;       // luma position of chroma sample 0
uniform float u_code_scale;  // normalised texel -> code value (255 or 65535)
uniform mat3 u_m;            // code values -> R'G'B'
uniform vec3 u_offset;

float chroma(sampler2D s, ivec2 i0, ivec2 i1, vec2 f) {
  float a = texelFetch(s, i0, 0).r, b = texelFetch(s, ivec2(i1.x, i0.y), 0).r;
  float c = texelFetch(s, ivec2(i0.x, i1.y), 0).r, d = texelFetch(s, i1, 0).r;
  float top = a + f.x * (b - a), bottom = c + f.x * (d - c);
  return (top + f.y * (bottom - top)) * u_code_scale;
}

void main() {
  ivec2 p = ivec2(int(gl_FragCoord.x), u_size.y - 1 - int(gl_FragCoord.y));
  if (u_rgb == 1) {
    frag = vec4(texelFetch(u_plane0, p, 0).rgb, 1.0);
    return;
  }
  vec2 c = (vec2(p) - u_siting) / u_chroma_step;
  vec2 c0 = floor(c);
  ivec2 i0 = clamp(ivec2(c0), ivec2(0), u_chroma_size - 1);
  ivec2 i1 = clamp(ivec2(c0) + 1, ivec2(0), u_chroma_size - 1);
  vec3 codes = vec3(texelFetch(u_plane0, p, 0).r * u_code_scale,
                    chroma(u_plane1, i0, i1, c - c0), chroma(u_plane2, i0, i1, c - c0));
  frag = vec4(clamp(u_m * codes + u_offset, 0.0, 1.0), 1.0);
}
)";

/// One source plane: a texture reallocated only when its size or layout changes.
struct PlaneTexture {
  unsigned id = 0;
  int width = 0, height = 0;
  GLenum internal = 0;
  ~PlaneTexture() {
    if (id) glDeleteTextures(1, &id);
  }
  /// Uploads `m` (CV_8UC1, CV_16UC1, CV_8UC3 or CV_32FC3; rows may be padded) as it is.
  void upload(const cv::Mat& m) {
    GLenum internal_fmt = 0, fmt = 0, type = 0;
    switch (m.type()) {
      case CV_8UC1: internal_fmt = GL_R8; fmt = GL_RED; type = GL_UNSIGNED_BYTE; break;
      case CV_16UC1: internal_fmt = GL_R16; fmt = GL_RED; type = GL_UNSIGNED_SHORT; break;
      case CV_8UC3: internal_fmt = GL_RGB8; fmt = GL_RGB; type = GL_UNSIGNED_BYTE; break;
      case CV_32FC3: internal_fmt = GL_RGB32F; fmt = GL_RGB; type = GL_FLOAT; break;
      default: throw GlError("VideoLayerGl: unsupported plane type " + std::to_string(m.type()));
    }
    if (!id || width != m.cols || height != m.rows || internal != internal_fmt) {
      if (id) glDeleteTextures(1, &id);
      glGenTextures(1, &id);
      glBindTexture(GL_TEXTURE_2D, id);
      glTexStorage2D(GL_TEXTURE_2D, 1, internal_fmt, m.cols, m.rows);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      width = m.cols;
      height = m.rows;
      internal = internal_fmt;
    }
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(m.step[0] / m.elemSize()));
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m.cols, m.rows, fmt, type, m.data);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    check_gl("VideoLayerGl plane upload");
  }
};

}  // namespace

struct VideoLayerGl::Impl {
  GlProgram program;
  GlProgram convert;
  GlTexture texture;
  unsigned vao = 0;
  int depth = -1;
  TexFormat format = TexFormat::RGBA8;
  unsigned fbo = 0;  //!< renders into level 0 of `texture` (the conversion pass)
  std::array<PlaneTexture, 3> planes;

  /// (Re)allocates the mipmapped equirect texture for this size and format.
  bool ensure_texture(int w, int h, TexFormat f) {
    if (texture && texture.width() == w && texture.height() == h && format == f) return false;
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(w, h))));
    texture = GlTexture(w, h, f, levels);
    texture.set_sampling(true, true);
    format = f;
    if (fbo) glDeleteFramebuffers(1, &fbo);
    fbo = 0;
    return true;
  }
};

VideoLayerGl::VideoLayerGl() : impl_(std::make_unique<Impl>()) {
  impl_->program = GlProgram::build("video_layer", fullscreen_vertex_source(), kFragment);
  impl_->convert = GlProgram::build("video_layer_convert", fullscreen_vertex_source(), kConvertFragment);
  glGenVertexArrays(1, &impl_->vao);
}

VideoLayerGl::~VideoLayerGl() {
  if (impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
  if (impl_->fbo) glDeleteFramebuffers(1, &impl_->fbo);
}

void VideoLayerGl::set_frame(const cv::Mat& equirect) {
  if (equirect.empty()) throw GlError("VideoLayerGl::set_frame: empty frame");
  const int depth = equirect.depth();
  impl_->ensure_texture(equirect.cols, equirect.rows,
                        depth == CV_8U ? TexFormat::RGBA8 : TexFormat::RGBA32F);
  impl_->depth = depth;
  impl_->texture.upload(equirect);
  impl_->texture.generate_mipmaps();
}

void VideoLayerGl::set_frame(const io::Picture& pic) {
  if (pic.empty()) throw GlError("VideoLayerGl::set_frame: empty picture");
  Impl& m = *impl_;
  const bool ycbcr = pic.is_ycbcr();
  const bool deep = ycbcr ? pic.ycbcr.bit_depth > 8 : pic.rgb.depth() != CV_8U;
  m.ensure_texture(pic.width(), pic.height(), deep ? TexFormat::RGBA16F : TexFormat::RGBA8);
  m.depth = deep ? CV_32F : CV_8U;
  if (ycbcr)
    for (std::size_t i = 0; i < 3; ++i) m.planes[i].upload(pic.planes[i]);
  else
    m.planes[0].upload(pic.rgb);

  GLint previous_fbo = 0, viewport[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_fbo);
  glGetIntegerv(GL_VIEWPORT, viewport);
  if (!m.fbo) {
    glGenFramebuffers(1, &m.fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m.texture.id(), 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw GlError("VideoLayerGl: the conversion target is incomplete");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, m.fbo);
  glViewport(0, 0, pic.width(), pic.height());
  const GlProgram& p = m.convert;
  p.use();
  for (int i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, m.planes[static_cast<std::size_t>(ycbcr ? i : 0)].id);
    const std::string name = "u_plane" + std::to_string(i);
    glUniform1i(p.uniform(name.c_str()), i);
  }
  glUniform1i(p.uniform("u_rgb"), ycbcr ? 0 : 1);
  glUniform2i(p.uniform("u_size"), pic.width(), pic.height());
  if (ycbcr) {
    const io::YcbcrInfo& c = pic.ycbcr;
    const io::AffineMap3 a = io::ycbcr_to_rgb_map(c);
    float mat[9], off[3];
    for (int i = 0; i < 9; ++i) mat[i] = static_cast<float>(a.m[static_cast<std::size_t>(i)]);
    for (int i = 0; i < 3; ++i) off[i] = static_cast<float>(a.offset[static_cast<std::size_t>(i)]);
    glUniform2i(p.uniform("u_chroma_size"), pic.planes[1].cols, pic.planes[1].rows);
    glUniform2f(p.uniform("u_chroma_step"), static_cast<float>(1 << c.log2_chroma_w),
                static_cast<float>(1 << c.log2_chroma_h));
    glUniform2f(p.uniform("u_siting"), static_cast<float>(c.chroma_x), static_cast<float>(c.chroma_y));
    glUniform1f(p.uniform("u_code_scale"), pic.planes[0].depth() == CV_16U ? 65535.0f : 255.0f);
    glUniformMatrix3fv(p.uniform("u_m"), 1, GL_TRUE, mat);  // row-major in, GLSL is column-major
    glUniform3fv(p.uniform("u_offset"), 1, off);
  }
  glDisable(GL_BLEND);
  glBindVertexArray(m.vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glActiveTexture(GL_TEXTURE0);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_fbo));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  m.texture.generate_mipmaps();
  check_gl("VideoLayerGl::set_frame(picture)");
}

void VideoLayerGl::render(const GlTarget& target, const RenderView& v, LodMode lod) {
  if (!impl_->texture) throw GlError("VideoLayerGl::render: no frame uploaded");
  target.bind();
  const GlProgram& p = impl_->program;
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, impl_->texture.id());
  glUniform1i(p.uniform("u_equirect"), 0);
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

const GlTexture& VideoLayerGl::texture() const { return impl_->texture; }

}  // namespace vdfx::xr
