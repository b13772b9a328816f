/// @file
/// @brief VideoLayerGl: per-pixel ray into the mipmapped equirect texture.
#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "effects/glsl_common.h"
#include "io/ycbcr.h"
#include "xr/gl_context.h"
#include "xr/gl_program.h"
#include "xr/video_layer.h"

namespace vdfx::xr {
namespace {

// After the shared constants, pinhole and equirect mapping (effects/glsl_common.h).
constexpr const char* kFragment = R"(out vec4 frag;
uniform sampler2D u_equirect;
uniform mat3 u_rot;      // eye -> world
uniform int u_lod_mode;  // 0 analytic, 1 hardware derivatives, 2 base level
// Y'CbCr source (u_ycbcr = 1): planes uploaded top row first (v, not t), converted per sample.
uniform int u_ycbcr;
uniform sampler2D u_plane0, u_plane1, u_plane2;
uniform vec2 u_chroma_scale, u_chroma_offset;  // luma (u, v) -> chroma (u, v), siting included
uniform float u_code_scale;  // normalised texel -> code value (255 or 65535)
uniform mat3 u_m;            // code values -> R'G'B' (io/ycbcr.h)
uniform vec3 u_offset;

// (du, dv) for a change e of the (unnormalised) ray d; see video_layer.h for the formulas.
vec2 uv_differential(vec3 d, vec3 e) {
  float h2 = max(dot(d.xz, d.xz), 1e-12);
  float h = sqrt(h2);
  float daz = (-d.z * e.x + d.x * e.z) / h2;
  float dh = (d.x * e.x + d.z * e.z) / h;
  float dalt = (h * e.y - d.y * dh) / (h2 + d.y * d.y);
  return vec2(daz / (2.0 * PI), dalt / PI);
}

// The video at (u, t) with screen-space gradients gx, gy (lod < 0: level 0 only).
vec3 sample_video(vec2 uv, vec2 gx, vec2 gy, bool base) {
  if (u_ycbcr == 0)
    return base ? textureLod(u_equirect, uv, 0.0).rgb : textureGrad(u_equirect, uv, gx, gy).rgb;
  vec2 p = vec2(uv.x, 1.0 - uv.y), px = vec2(gx.x, -gx.y), py = vec2(gy.x, -gy.y);
  vec2 c = p * u_chroma_scale + u_chroma_offset;
  vec3 codes;
  if (base) {
    codes = vec3(textureLod(u_plane0, p, 0.0).r, textureLod(u_plane1, c, 0.0).r, textureLod(u_plane2, c, 0.0).r);
  } else {
    vec2 cx = px * u_chroma_scale, cy = py * u_chroma_scale;
    codes = vec3(textureGrad(u_plane0, p, px, py).r, textureGrad(u_plane1, c, cx, cy).r,
                 textureGrad(u_plane2, c, cx, cy).r);
  }
  return clamp(u_m * (codes * u_code_scale) + u_offset, 0.0, 1.0);
}

void main() {
  vec3 d = u_rot * pinhole_ray();
  vec2 uv = equirect_uv(d);
  vec3 c;
  if (u_lod_mode == 0) {
    vec3 ex = u_rot[0] * ((u_tan.y - u_tan.x) / u_size.x);
    vec3 ey = u_rot[1] * ((u_tan.w - u_tan.z) / u_size.y);
    c = sample_video(uv, uv_differential(d, ex), uv_differential(d, ey), false);
  } else if (u_lod_mode == 1) {
    vec2 gx = dFdx(uv), gy = dFdy(uv);
    float u2 = fract(uv.x + 0.5);  // jumps at azimuth 0 instead of at the seam
    float gx2 = dFdx(u2), gy2 = dFdy(u2);
    if (abs(gx2) < abs(gx.x)) gx.x = gx2;
    if (abs(gy2) < abs(gy.x)) gy.x = gy2;
    c = sample_video(uv, gx, gy, false);
  } else {
    c = sample_video(uv, vec2(0.0), vec2(0.0), true);
  }
  frag = vec4(c, 1.0);
}
)";

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
  /// Uploads `m` (CV_8UC1 or CV_16UC1; rows may be padded) as it is and rebuilds the mips.
  void upload(const cv::Mat& m) {
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
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      width = m.cols;
      height = m.rows;
      internal = internal_fmt;
    }
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(m.step[0] / m.elemSize()));
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m.cols, m.rows, GL_RED,
                    deep ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE, m.data);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glGenerateMipmap(GL_TEXTURE_2D);
    check_gl("VideoLayerGl plane upload");
  }
};

}  // namespace

struct VideoLayerGl::Impl {
  GlProgram program;
  GlTexture texture;  //!< RGB source (set_frame(cv::Mat), RGB pictures)
  unsigned vao = 0;
  int depth = -1;
  bool ycbcr = false;  //!< the planes below are the source
  std::array<PlaneTexture, 3> planes;
  io::YcbcrInfo info;
  float chroma_scale[2] = {1, 1}, chroma_offset[2] = {0, 0};
};

VideoLayerGl::VideoLayerGl() : impl_(std::make_unique<Impl>()) {
  namespace glsl = effects::glsl;
  const std::string fragment =
      std::string(glsl::kConstants) + glsl::kPinhole + glsl::kEquirect + kFragment;
  impl_->program = GlProgram::build("video_layer", fullscreen_vertex_source(), fragment);
  glGenVertexArrays(1, &impl_->vao);
}

VideoLayerGl::~VideoLayerGl() {
  if (impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
}

void VideoLayerGl::set_frame(const cv::Mat& equirect) {
  if (equirect.empty()) throw GlError("VideoLayerGl::set_frame: empty frame");
  const int depth = equirect.depth();
  GlTexture& t = impl_->texture;
  if (!t || t.width() != equirect.cols || t.height() != equirect.rows || impl_->depth != depth) {
    const int levels = full_mip_levels(equirect.cols, equirect.rows);
    t = GlTexture(equirect.cols, equirect.rows,
                  depth == CV_8U ? TexFormat::RGBA8 : TexFormat::RGBA32F, levels);
    t.set_sampling(true, true);
    impl_->depth = depth;
  }
  t.upload(equirect);
  t.generate_mipmaps();
  impl_->ycbcr = false;
}

void VideoLayerGl::set_frame(const io::Picture& pic) {
  if (pic.empty()) throw GlError("VideoLayerGl::set_frame: empty picture");
  if (!pic.is_ycbcr()) {
    // Stills and RGB codecs: one channel swap into the RGB path (rare, and once for a still).
    cv::Mat bgr;
    cv::cvtColor(pic.rgb, bgr, cv::COLOR_RGB2BGR);
    set_frame(bgr);
    return;
  }
  Impl& m = *impl_;
  for (std::size_t i = 0; i < 3; ++i) m.planes[i].upload(pic.planes[i]);
  m.info = pic.ycbcr;
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
    m.chroma_scale[a] = static_cast<float>(size[a] / (step[a] * chroma[a]));
    m.chroma_offset[a] = static_cast<float>((0.5 - (0.5 + siting[a]) / step[a]) / chroma[a]);
  }
  m.ycbcr = true;
}

void VideoLayerGl::render(const GlTarget& target, const RenderView& v, LodMode lod) {
  Impl& m = *impl_;
  target.bind();
  if (!has_frame()) {
    // No frame decoded yet (a video still loading): a dark, neutral field instead of a failure,
    // so the first frames of a window never depend on the decoder's head start.
    glClearColor(kNoFrameGrey, kNoFrameGrey, kNoFrameGrey, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  const GlProgram& p = impl_->program;
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, m.ycbcr ? 0 : m.texture.id());
  glUniform1i(p.uniform("u_equirect"), 0);
  glUniform1i(p.uniform("u_ycbcr"), m.ycbcr ? 1 : 0);
  if (m.ycbcr) {
    for (int i = 0; i < 3; ++i) {
      glActiveTexture(GL_TEXTURE1 + i);
      glBindTexture(GL_TEXTURE_2D, m.planes[static_cast<std::size_t>(i)].id);
      const std::string name = "u_plane" + std::to_string(i);
      glUniform1i(p.uniform(name.c_str()), 1 + i);
    }
    glActiveTexture(GL_TEXTURE0);
    const io::AffineMap3 a = io::ycbcr_to_rgb_map(m.info);
    float mat[9], off[3];
    for (std::size_t i = 0; i < 9; ++i) mat[i] = static_cast<float>(a.m[i]);
    for (std::size_t i = 0; i < 3; ++i) off[i] = static_cast<float>(a.offset[i]);
    glUniformMatrix3fv(p.uniform("u_m"), 1, GL_TRUE, mat);  // row-major in, GLSL is column-major
    glUniform3fv(p.uniform("u_offset"), 1, off);
    glUniform1f(p.uniform("u_code_scale"), m.planes[0].internal == GL_R16 ? 65535.0f : 255.0f);
    glUniform2f(p.uniform("u_chroma_scale"), m.chroma_scale[0], m.chroma_scale[1]);
    glUniform2f(p.uniform("u_chroma_offset"), m.chroma_offset[0], m.chroma_offset[1]);
  }
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
  return impl_->texture;
}
bool VideoLayerGl::has_frame() const {
  return impl_->ycbcr || static_cast<bool>(impl_->texture);
}

}  // namespace vdfx::xr
