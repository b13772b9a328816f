/// @file
/// @brief GrainGl: the shader-style pass and the instanced particles generated in the vertex
/// stage.
#include "xr/render/grain_gl.h"

#include <epoxy/gl.h>

#include <cmath>
#include <vector>

#include "effects/grain_render.h"
#include "effects/grain_shaders.h"
#include "xr/render/gl_context.h"
#include "xr/render/gl_program.h"

namespace vdfx::xr {
namespace {

constexpr double kNearM = 0.01;

}  // namespace

struct GrainGl::Impl {
  GlProgram shader, particles;
  unsigned empty_vao = 0;
  std::vector<effects::GrainFrame> layers;
  GrainLayerStats stats;

  void draw_shader(const RenderView& view, int width, int height, const effects::GrainFrame& f) {
    const effects::ShaderGrainUniforms u =
        effects::shader_grain_uniforms(f, view.orientation, view.position, view.tangents());
    shader.use();
    const auto loc = [&](const char* n) { return shader.uniform(n); };
    glUniform4iv(loc("u_perm"), 64, u.perm.data());
    glUniform1i(loc("u_style"), u.style);
    glUniformMatrix3fv(loc("u_eye_to_grain"), 1, GL_FALSE, u.eye_to_grain.data());
    glUniform3fv(loc("u_eye"), 1, u.eye.data());
    glUniform1f(loc("u_distance"), u.distance);
    glUniform1f(loc("u_inv_cell"), u.inv_cell);
    glUniform3fv(loc("u_offset1"), 1, u.offset1.data());
    glUniform3fv(loc("u_offset2"), 1, u.offset2.data());
    glUniform1f(loc("u_octave2"), u.octave2);
    glUniform1f(loc("u_gain"), u.gain);
    glUniform1f(loc("u_floor"), u.floor);
    glUniform4f(loc("u_tan"), u.tangents[0], u.tangents[1], u.tangents[2], u.tangents[3]);
    glUniform2f(loc("u_size"), static_cast<float>(width), static_cast<float>(height));
    glBindVertexArray(empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++stats.shader_draws;
  }

  /// The uniforms from which the vertex stage generates the particles (grain_particle).
  void set_particle_stream(const effects::GrainFrame& f) {
    const auto loc = [&](const char* n) { return particles.uniform(n); };
    const effects::GrainSettings& s = f.settings;
    const auto [r0, r1] = effects::object_cloud_radii(s, 0);
    const auto [q0, q1] = effects::object_cloud_radii(s, 1);
    glUniform1ui(loc("u_key"), f.particle_key);
    glUniform1i(loc("u_cloud"), f.style == effects::GrainStyle::FreeCloud ? 1 : 0);
    glUniform1ui(loc("u_shell_threshold"), effects::kObjectShellThreshold);
    glUniform4f(loc("u_radii"), static_cast<float>(r0), static_cast<float>(std::log(r1 / r0)),
                static_cast<float>(q0), static_cast<float>(std::log(q1 / q0)));
    glUniform2f(loc("u_cylinder"), static_cast<float>(s.get(effects::GrainSetting::RadiusM)),
                static_cast<float>(s.get(effects::GrainSetting::HeightM)));
    glUniform2f(loc("u_extent_range"), static_cast<float>(effects::kParticleMinExtentM),
                static_cast<float>(effects::kParticleMaxExtentM - effects::kParticleMinExtentM));
    glUniform1f(loc("u_min_opacity"), static_cast<float>(effects::kMinParticleOpacity));
  }

  void draw_particles(const RenderView& view, int width, int height, const effects::GrainFrame& f) {
    const auto count = static_cast<GLsizei>(f.settings.get(effects::GrainSetting::Count));
    if (count <= 0) return;
    // Positions are relative to the head: the eye at (view.position - head) sees them, with an
    // infinite far plane (the surrounding volume reaches kilometres).
    RenderView local = view;
    local.position = view.position - f.head.position;
    const Eigen::Matrix4f vp = (local.projection(kNearM, 0.0) * local.world_to_eye()).cast<float>();
    const Eigen::Vector3f eye = local.position.cast<float>();
    const Eigen::Vector3f up = view.orientation.col(1).cast<float>();
    const Eigen::Vector3f right = view.orientation.col(0).cast<float>();
    const double px_per_tan =
        std::min(width / (view.tan_right - view.tan_left), height / (view.tan_up - view.tan_down));
    particles.use();
    set_particle_stream(f);
    const auto loc = [&](const char* n) { return particles.uniform(n); };
    glUniformMatrix4fv(loc("u_view_proj"), 1, GL_FALSE, vp.data());
    glUniform3fv(loc("u_eye"), 1, eye.data());
    glUniform3fv(loc("u_eye_up"), 1, up.data());
    glUniform3fv(loc("u_eye_right"), 1, right.data());
    glUniform1f(loc("u_size"), static_cast<float>(f.params.size));
    glUniform1f(loc("u_intensity"), static_cast<float>(f.params.intensity));
    glUniform1f(loc("u_px_per_tan"), static_cast<float>(px_per_tan));
    glUniform1f(loc("u_near_start"), static_cast<float>(effects::kParticleNearFadeStartM));
    glUniform1f(loc("u_near_end"), static_cast<float>(effects::kParticleNearFadeEndM));
    glUniform1f(loc("u_min_radius_px"), static_cast<float>(effects::kParticleMinRadiusPx));
    glUniform1f(loc("u_max_radius_rad"), static_cast<float>(effects::kParticleMaxRadiusRad));
    glUniform1f(loc("u_floor"), static_cast<float>(effects::kGrainFloor));
    glBindVertexArray(empty_vao);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
    ++stats.particle_draws;
    stats.particles_drawn += count;
  }
};

GrainGl::GrainGl() : impl_(std::make_unique<Impl>()) {
  impl_->shader = GlProgram::build("grain_shader", fullscreen_vertex_source(),
                                   effects::grain_shader_fragment_source());
  impl_->particles = GlProgram::build("grain_particles", effects::grain_particle_vertex_source(),
                                      effects::grain_particle_fragment_source());
  glGenVertexArrays(1, &impl_->empty_vao);
  check_gl("GrainGl");
}

GrainGl::~GrainGl() {
  if (!impl_) return;
  if (impl_->empty_vao) glDeleteVertexArrays(1, &impl_->empty_vao);
}

void GrainGl::set_layers(std::vector<effects::GrainFrame> layers) {
  impl_->layers = std::move(layers);
}
const std::vector<effects::GrainFrame>& GrainGl::layers() const {
  return impl_->layers;
}
GrainLayerStats GrainGl::stats() const {
  return impl_->stats;
}

void GrainGl::draw(const RenderView& view, int /*eye*/, int width, int height) {
  Impl& m = *impl_;
  if (m.layers.empty()) return;
  glEnable(GL_BLEND);
  // out = src0 + dst * src1 on colour (the grain modulates what is there); alpha is left alone.
  glBlendFuncSeparate(GL_ONE, GL_SRC1_COLOR, GL_ZERO, GL_ONE);
  for (const effects::GrainFrame& f : m.layers) {
    if (!(f.params.intensity > 0.0)) continue;
    if (effects::is_volumetric(f.style))
      m.draw_particles(view, width, height, f);
    else
      m.draw_shader(view, width, height, f);
  }
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

}  // namespace vdfx::xr
