/// @file
/// @brief VideoLayerGl: per-pixel ray into the mipmapped equirect texture.
#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

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

}  // namespace

struct VideoLayerGl::Impl {
  GlProgram program;
  GlTexture texture;
  unsigned vao = 0;
  int depth = -1;
};

VideoLayerGl::VideoLayerGl() : impl_(std::make_unique<Impl>()) {
  impl_->program = GlProgram::build("video_layer", fullscreen_vertex_source(), kFragment);
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
    const int levels =
        1 + static_cast<int>(std::floor(std::log2(std::max(equirect.cols, equirect.rows))));
    t = GlTexture(equirect.cols, equirect.rows,
                  depth == CV_8U ? TexFormat::RGBA8 : TexFormat::RGBA32F, levels);
    t.set_sampling(true, true);
    impl_->depth = depth;
  }
  t.upload(equirect);
  t.generate_mipmaps();
}

void VideoLayerGl::render(const GlTarget& target, const RenderView& v, LodMode lod) {
  target.bind();
  if (!impl_->texture) {
    // No frame decoded yet (a video still loading): a dark, neutral field instead of a failure,
    // so the first frames of a window never depend on the decoder's head start.
    glClearColor(kNoFrameGrey, kNoFrameGrey, kNoFrameGrey, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
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
bool VideoLayerGl::has_frame() const { return static_cast<bool>(impl_->texture); }

}  // namespace vdfx::xr
