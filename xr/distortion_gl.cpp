/// @file
/// @brief DistortionGl: pixel and mesh pre-distortion, through-the-lens pass.
#include <epoxy/gl.h>

#include <cmath>
#include <limits>
#include <vector>

#include "xr/distortion_gl.h"
#include "xr/gl_context.h"
#include "xr/gl_program.h"

namespace vdfx::xr {
namespace {

// Shared GLSL: the lens model and the tangent <-> texture mapping of one eye.
constexpr const char* kLensGlsl = R"(
uniform vec4 u_tan;       // left, right, down, up tangents of eye buffer and panel
uniform vec2 u_size;      // target size in pixels
uniform vec2 u_centre;    // optical centre, tangent units
uniform vec2 u_coef;      // c1, c2
uniform vec3 u_scale;     // per-channel radial scale s_c
uniform float u_ru_max;   // largest r_u where the model still increases
uniform float u_rd_max;   // f(u_ru_max)
float lens_forward(float r) { float r2 = r * r; return r * (1.0 + r2 * (u_coef.x + u_coef.y * r2)); }
vec2 tan_at_fragment() {
  vec2 q = gl_FragCoord.xy / u_size;
  return vec2(mix(u_tan.x, u_tan.y, q.x), mix(u_tan.z, u_tan.w, q.y));
}
vec2 tan_to_uv(vec2 t) {
  return vec2((t.x - u_tan.x) / (u_tan.y - u_tan.x), (t.y - u_tan.z) / (u_tan.w - u_tan.z));
}
bool inside(vec2 uv) { return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))); }
)";

constexpr const char* kPixelFragment = R"(
out vec4 frag;
uniform sampler2D u_src;
uniform int u_iterations;
uniform int u_output_uv;
float lens_inverse(float rd) {
  float r = min(rd, 0.999 * u_ru_max);
  for (int i = 0; i < u_iterations; ++i) {
    float r2 = r * r;
    float step = (lens_forward(r) - rd) / (1.0 + r2 * (3.0 * u_coef.x + 5.0 * u_coef.y * r2));
    r = clamp(r - step, 0.0, u_ru_max);
  }
  return r;
}
void main() {
  vec2 rel = tan_at_fragment() - u_centre;
  float rd = length(rel);
  vec2 dir = rd > 0.0 ? rel / rd : vec2(0.0);
  vec3 c = vec3(0.0);
  vec2 uv_green = vec2(-1.0);
  for (int ch = 0; ch < 3; ++ch) {
    float r = rd / u_scale[ch];
    if (r > u_rd_max) continue;  // no inverse: black, never a folded image
    vec2 uv = tan_to_uv(u_centre + dir * lens_inverse(r));
    if (ch == 1) uv_green = uv;
    if (inside(uv)) c[ch] = texture(u_src, uv)[ch];
  }
  frag = u_output_uv != 0 ? vec4(uv_green * vec2(textureSize(u_src, 0)), 0.0, 1.0) : vec4(c, 1.0);
}
)";

constexpr const char* kMeshVertex = R"(
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec2 a_uv_r;
layout(location = 2) in vec2 a_uv_g;
layout(location = 3) in vec2 a_uv_b;
out vec2 v_r;
out vec2 v_g;
out vec2 v_b;
void main() {
  v_r = a_uv_r;
  v_g = a_uv_g;
  v_b = a_uv_b;
  gl_Position = vec4(a_pos, 0.0, 1.0);
}
)";

constexpr const char* kMeshFragment = R"(
in vec2 v_r;
in vec2 v_g;
in vec2 v_b;
out vec4 frag;
uniform sampler2D u_src;
uniform int u_output_uv;
void main() {
  // The mesh interpolates UVs; the valid-radius cut is exact per fragment, not per triangle.
  float rd = length(tan_at_fragment() - u_centre);
  vec3 c = vec3(0.0);
  if (rd / u_scale.r <= u_rd_max && inside(v_r)) c.r = texture(u_src, v_r).r;
  if (rd / u_scale.g <= u_rd_max && inside(v_g)) c.g = texture(u_src, v_g).g;
  if (rd / u_scale.b <= u_rd_max && inside(v_b)) c.b = texture(u_src, v_b).b;
  frag = u_output_uv != 0 ? vec4(v_g * vec2(textureSize(u_src, 0)), 0.0, 1.0) : vec4(c, 1.0);
}
)";

constexpr const char* kThroughLensFragment = R"(
out vec4 frag;
uniform sampler2D u_panel;
void main() {
  vec2 rel = tan_at_fragment() - u_centre;
  float ru = length(rel);
  vec2 dir = ru > 0.0 ? rel / ru : vec2(0.0);
  vec3 c = vec3(0.0);
  if (ru <= u_ru_max) {
    for (int ch = 0; ch < 3; ++ch) {
      vec2 uv = tan_to_uv(u_centre + dir * (u_scale[ch] * lens_forward(ru)));
      if (inside(uv)) c[ch] = texture(u_panel, uv)[ch];
    }
  }
  frag = vec4(c, 1.0);
}
)";

float finite_or_big(double x) {
  return std::isfinite(x) ? static_cast<float>(x) : 1e30f;
}

void set_lens_uniforms(const GlProgram& p, const GlTarget& target, const RenderView& eye,
                       const LensDistortion& lens, const Eigen::Vector3d& scale) {
  glUniform4f(p.uniform("u_tan"), static_cast<float>(eye.tan_left), static_cast<float>(eye.tan_right),
              static_cast<float>(eye.tan_down), static_cast<float>(eye.tan_up));
  glUniform2f(p.uniform("u_size"), static_cast<float>(target.width()),
              static_cast<float>(target.height()));
  glUniform2f(p.uniform("u_centre"), static_cast<float>(eye.optical_centre_tan.x()),
              static_cast<float>(eye.optical_centre_tan.y()));
  glUniform2f(p.uniform("u_coef"), static_cast<float>(lens.c1), static_cast<float>(lens.c2));
  glUniform3f(p.uniform("u_scale"), static_cast<float>(scale.x()), static_cast<float>(scale.y()),
              static_cast<float>(scale.z()));
  glUniform1f(p.uniform("u_ru_max"), finite_or_big(lens.max_valid_undistorted_radius()));
  glUniform1f(p.uniform("u_rd_max"), finite_or_big(lens.max_valid_distorted_radius()));
}

struct MeshKey {
  int n = 0;
  double c[2] = {};
  double s[3] = {};
  double tan[4] = {};
  double centre[2] = {};
  bool operator==(const MeshKey&) const = default;
};

}  // namespace

struct DistortionGl::Impl {
  GlProgram pixel, mesh, through;
  unsigned empty_vao = 0;
  unsigned mesh_vao = 0, mesh_vbo = 0, mesh_ibo = 0;
  int mesh_indices = 0;
  MeshKey mesh_key;

  void build_mesh(const MeshKey& key, const RenderView& eye, const LensDistortion& lens,
                  const Eigen::Vector3d& scale) {
    const int n = key.n;
    // Per vertex: position (2), uv r (2), uv g (2), uv b (2).
    std::vector<float> v;
    v.reserve(static_cast<size_t>(n * n * 8));
    const double rd_max = lens.max_valid_distorted_radius();
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double a = static_cast<double>(i) / (n - 1), b = static_cast<double>(j) / (n - 1);
        v.push_back(static_cast<float>(2 * a - 1));
        v.push_back(static_cast<float>(2 * b - 1));
        const Eigen::Vector2d t(eye.tan_left + a * (eye.tan_right - eye.tan_left),
                                eye.tan_down + b * (eye.tan_up - eye.tan_down));
        const Eigen::Vector2d rel = t - eye.optical_centre_tan;
        const double rd = rel.norm();
        for (int ch = 0; ch < 3; ++ch) {
          const double r = rd / scale[ch];
          // Beyond the valid radius the vertex keeps the UV at the radius limit, so the
          // interpolation stays smooth up to the exact per-fragment cut.
          const double ru = r <= rd_max ? lens.inverse(r, 50) : lens.max_valid_undistorted_radius();
          const Eigen::Vector2d tu =
              eye.optical_centre_tan +
              (rd > 0 ? Eigen::Vector2d(rel * (ru / rd)) : Eigen::Vector2d::Zero());
          const Eigen::Vector2d uv((tu.x() - eye.tan_left) / (eye.tan_right - eye.tan_left),
                                   (tu.y() - eye.tan_down) / (eye.tan_up - eye.tan_down));
          v.push_back(static_cast<float>(uv.x()));
          v.push_back(static_cast<float>(uv.y()));
        }
      }
    std::vector<unsigned> idx;
    idx.reserve(static_cast<size_t>((n - 1) * (n - 1) * 6));
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const unsigned k = static_cast<unsigned>(j * n + i), un = static_cast<unsigned>(n);
        for (unsigned q : {k, k + 1, k + un, k + 1, k + un + 1, k + un}) idx.push_back(q);
      }
    if (!mesh_vao) {
      glGenVertexArrays(1, &mesh_vao);
      glGenBuffers(1, &mesh_vbo);
      glGenBuffers(1, &mesh_ibo);
    }
    glBindVertexArray(mesh_vao);
    glBindBuffer(GL_ARRAY_BUFFER, mesh_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh_ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(unsigned)),
                 idx.data(), GL_STATIC_DRAW);
    for (unsigned a = 0; a < 4; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float),
                            reinterpret_cast<const void*>(static_cast<uintptr_t>(a * 2 * sizeof(float))));
    }
    mesh_indices = static_cast<int>(idx.size());
    mesh_key = key;
    check_gl("distortion mesh upload");
  }
};

DistortionGl::DistortionGl() : impl_(std::make_unique<Impl>()) {
  const std::string lens = kLensGlsl;
  impl_->pixel = GlProgram::build("predistort_pixel", fullscreen_vertex_source(), lens + kPixelFragment);
  impl_->mesh = GlProgram::build("predistort_mesh", kMeshVertex, lens + kMeshFragment);
  impl_->through =
      GlProgram::build("through_lens", fullscreen_vertex_source(), lens + kThroughLensFragment);
  glGenVertexArrays(1, &impl_->empty_vao);
}

DistortionGl::~DistortionGl() {
  glDeleteVertexArrays(1, &impl_->empty_vao);
  if (impl_->mesh_vao) {
    glDeleteVertexArrays(1, &impl_->mesh_vao);
    glDeleteBuffers(1, &impl_->mesh_vbo);
    glDeleteBuffers(1, &impl_->mesh_ibo);
  }
}

void DistortionGl::predistort(const GlTexture& src, const GlTarget& panel, const RenderView& eye,
                              const LensDistortion& lens, const DistortionSettings& s) {
  const Eigen::Vector3d scale = s.correct_lca ? lens.lca_scale : Eigen::Vector3d::Ones();
  panel.bind();
  glDisable(GL_BLEND);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, src.id());
  if (s.method == DistortionMethod::Mesh) {
    if (s.mesh_n < 2) throw GlError("DistortionGl: mesh_n must be at least 2");
    const MeshKey key{s.mesh_n,
                      {lens.c1, lens.c2},
                      {scale.x(), scale.y(), scale.z()},
                      {eye.tan_left, eye.tan_right, eye.tan_down, eye.tan_up},
                      {eye.optical_centre_tan.x(), eye.optical_centre_tan.y()}};
    if (!(key == impl_->mesh_key)) impl_->build_mesh(key, eye, lens, scale);
    const GlProgram& p = impl_->mesh;
    p.use();
    glUniform1i(p.uniform("u_src"), 0);
    glUniform1i(p.uniform("u_output_uv"), s.output_sample_position ? 1 : 0);
    set_lens_uniforms(p, panel, eye, lens, scale);
    glBindVertexArray(impl_->mesh_vao);
    glDrawElements(GL_TRIANGLES, impl_->mesh_indices, GL_UNSIGNED_INT, nullptr);
    return;
  }
  const GlProgram& p = impl_->pixel;
  p.use();
  glUniform1i(p.uniform("u_src"), 0);
  set_lens_uniforms(p, panel, eye, lens, scale);
  // DistortionMethod::None: zero iterations of an identity lens reads the eye buffer 1:1.
  const bool none = s.method == DistortionMethod::None;
  if (none) {
    glUniform2f(p.uniform("u_coef"), 0.0f, 0.0f);
    glUniform3f(p.uniform("u_scale"), 1.0f, 1.0f, 1.0f);
    glUniform1f(p.uniform("u_ru_max"), 1e30f);
    glUniform1f(p.uniform("u_rd_max"), 1e30f);
  }
  glUniform1i(p.uniform("u_iterations"), none ? 0 : s.max_iterations);
  glUniform1i(p.uniform("u_output_uv"), s.output_sample_position ? 1 : 0);
  glBindVertexArray(impl_->empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void DistortionGl::through_lens(const GlTexture& panel, const GlTarget& seen, const RenderView& eye,
                                const LensDistortion& lens) {
  seen.bind();
  glDisable(GL_BLEND);
  const GlProgram& p = impl_->through;
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, panel.id());
  glUniform1i(p.uniform("u_panel"), 0);
  set_lens_uniforms(p, seen, eye, lens, lens.lca_scale);
  glBindVertexArray(impl_->empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace vdfx::xr
