/// @file
/// @brief DistortionGl: pixel and mesh pre-distortion, through-the-lens pass.
#include "xr/render/distortion_gl.h"

#include <epoxy/gl.h>

#include <cmath>
#include <limits>
#include <vector>

#include "effects/distortion_mesh.h"
#include "effects/glsl_common.h"
#include "xr/render/gl_context.h"
#include "xr/render/gl_program.h"

namespace vdfx::xr {
namespace {

// GLSL of the three lens passes: the lens model and the tangent -> texture mapping of one eye
// (after the shared pinhole, effects/glsl_common.h: u_tan spans the eye buffer and the display
// image alike).
constexpr const char* kLensGlsl = R"(
uniform vec2 u_centre;    // optical centre, tangent units (the optical axis: 0, 0)
uniform vec2 u_coef;      // c1, c2 (on radii normalised by u_norm_radius)
uniform float u_norm_radius;  // R of effects::LensParams
uniform vec3 u_scale;     // per-channel radial scale s_c
uniform float u_ru_max;   // largest normalised r_u where the model still increases
uniform float u_rd_max;   // f(u_ru_max)
float lens_forward(float r) { float r2 = r * r; return r * (1.0 + r2 * (u_coef.x + u_coef.y * r2)); }
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
    float r = rd / (u_scale[ch] * u_norm_radius);
    if (r > u_rd_max) continue;  // no inverse: black, never a folded image
    vec2 uv = tan_to_uv(u_centre + dir * (u_norm_radius * lens_inverse(r)));
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
  float rd = length(tan_at_fragment() - u_centre) / u_norm_radius;
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
  float ru = length(rel) / u_norm_radius;
  vec2 dir = ru > 0.0 ? normalize(rel) : vec2(0.0);
  vec3 c = vec3(0.0);
  if (ru <= u_ru_max) {
    for (int ch = 0; ch < 3; ++ch) {
      vec2 uv = tan_to_uv(u_centre + dir * (u_norm_radius * u_scale[ch] * lens_forward(ru)));
      if (inside(uv)) c[ch] = texture(u_panel, uv)[ch];
    }
  }
  frag = vec4(c, 1.0);
}
)";

float finite_or_big(double x) {
  return std::isfinite(x) ? static_cast<float>(x) : 1e30f;
}

Eigen::Vector3d lca_scale(const effects::LensModel& lens) {
  const auto& s = lens.params().lca_scale;
  return {s[0], s[1], s[2]};
}

void set_lens_uniforms(const GlProgram& p, const GlTarget& target, const RenderView& eye,
                       const effects::LensModel& lens, const Eigen::Vector3d& scale) {
  glUniform4f(p.uniform("u_tan"), static_cast<float>(eye.tan_left),
              static_cast<float>(eye.tan_right), static_cast<float>(eye.tan_down),
              static_cast<float>(eye.tan_up));
  glUniform2f(p.uniform("u_size"), static_cast<float>(target.width()),
              static_cast<float>(target.height()));
  glUniform2f(p.uniform("u_centre"), 0.0f, 0.0f);  // the lens is centred on the optical axis
  glUniform2f(p.uniform("u_coef"), static_cast<float>(lens.params().c1),
              static_cast<float>(lens.params().c2));
  glUniform1f(p.uniform("u_norm_radius"), static_cast<float>(lens.params().radius));
  glUniform3f(p.uniform("u_scale"), static_cast<float>(scale.x()), static_cast<float>(scale.y()),
              static_cast<float>(scale.z()));
  glUniform1f(p.uniform("u_ru_max"), finite_or_big(lens.max_undistorted_radius()));
  glUniform1f(p.uniform("u_rd_max"), finite_or_big(lens.max_distorted_radius()));
}

effects::EyeLens eye_lens(const RenderView& v, int width, int height,
                          const effects::LensModel& lens) {
  effects::EyeLens e;
  e.width = width;
  e.height = height;
  e.fov = {v.tan_left, v.tan_right, v.tan_up, v.tan_down};
  e.lens = lens;
  return e;
}

struct MeshKey {
  int n = 0;
  bool lca = true;
  double c[3] = {};
  double s[3] = {};
  double tan[4] = {};
  bool operator==(const MeshKey&) const = default;
};

}  // namespace

struct DistortionGl::Impl {
  GlProgram pixel, mesh, through;
  unsigned empty_vao = 0;
  unsigned mesh_vao = 0, mesh_vbo = 0, mesh_ibo = 0;
  int mesh_indices = 0;
  MeshKey mesh_key;

  void build_mesh(const MeshKey& key, const RenderView& eye, const effects::LensModel& lens,
                  int width, int height) {
    const effects::DistortionMesh mesh =
        effects::build_distortion_mesh(eye_lens(eye, width, height, lens), key.n, key.lca);
    // Per vertex: position (2), uv r (2), uv g (2), uv b (2). The mesh is y-down in pixels and
    // UVs; GL positions and texture t are y-up.
    std::vector<float> v;
    v.reserve(mesh.vertices.size() * 8);
    const effects::EyeLens el = eye_lens(eye, width, height, lens);
    for (const effects::MeshVertex& mv : mesh.vertices) {
      v.push_back(static_cast<float>(2.0 * mv.panel_px.x() / width - 1.0));
      v.push_back(static_cast<float>(1.0 - 2.0 * mv.panel_px.y() / height));
      for (int ch = 0; ch < 3; ++ch) {
        Eigen::Vector2d uv = mv.uv[static_cast<size_t>(ch)];
        if (!mv.valid[static_cast<size_t>(ch)]) {
          // Beyond the valid radius: the UV at the radius limit along the same direction keeps
          // the interpolation smooth up to the exact per-fragment cut.
          const Eigen::Vector2d t = el.pixel_to_tan(mv.panel_px);
          const double r = lens.params().radius * lens.max_undistorted_radius();
          uv = el.tan_to_uv(t.norm() > 0 ? Eigen::Vector2d(t.normalized() * r) : t);
        }
        v.push_back(static_cast<float>(uv.x()));
        v.push_back(static_cast<float>(1.0 - uv.y()));
      }
    }
    const auto& idx = mesh.indices;
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
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(),
                 GL_STATIC_DRAW);
    for (unsigned a = 0; a < 4; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(
          a, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float),
          reinterpret_cast<const void*>(static_cast<uintptr_t>(a * 2 * sizeof(float))));
    }
    mesh_indices = static_cast<int>(idx.size());
    mesh_key = key;
    check_gl("distortion mesh upload");
  }
};

DistortionGl::DistortionGl() : impl_(std::make_unique<Impl>()) {
  const std::string lens = std::string(effects::glsl::kPinhole) + kLensGlsl;
  impl_->pixel =
      GlProgram::build("predistort_pixel", fullscreen_vertex_source(), lens + kPixelFragment);
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
                              const effects::LensModel& lens, const DistortionSettings& s) {
  const Eigen::Vector3d scale = s.correct_lca ? lca_scale(lens) : Eigen::Vector3d::Ones();
  panel.bind();
  glDisable(GL_BLEND);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, src.id());
  if (s.method == DistortionMethod::Mesh) {
    if (s.mesh_n < 2) throw GlError("DistortionGl: mesh_n must be at least 2");
    const auto& lp = lens.params();
    const MeshKey key{s.mesh_n,
                      s.correct_lca,
                      {lp.c1, lp.c2, lp.radius},
                      {scale.x(), scale.y(), scale.z()},
                      {eye.tan_left, eye.tan_right, eye.tan_down, eye.tan_up}};
    if (!(key == impl_->mesh_key)) impl_->build_mesh(key, eye, lens, panel.width(), panel.height());
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
    glUniform1f(p.uniform("u_norm_radius"), 1.0f);
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
                                const effects::LensModel& lens) {
  seen.bind();
  glDisable(GL_BLEND);
  const GlProgram& p = impl_->through;
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, panel.id());
  glUniform1i(p.uniform("u_panel"), 0);
  set_lens_uniforms(p, seen, eye, lens, lca_scale(lens));
  glBindVertexArray(impl_->empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace vdfx::xr
