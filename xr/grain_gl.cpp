/// @file
/// @brief GrainLayerGl: the shader-style pass and the instanced particles.
#include "xr/grain_gl.h"

#include <epoxy/gl.h>

#include <array>
#include <map>
#include <vector>

#include "effects/grain_render.h"
#include "effects/grain_shaders.h"
#include "xr/gl_context.h"
#include "xr/gl_program.h"

namespace vdfx::xr {
namespace {

constexpr int kFloatsPerParticle = 12;  // centre 3, extent 3, rotation 4, shade 2
constexpr double kNearM = 0.01;

struct Buffers {
  unsigned vao = 0, vbo = 0;
  std::shared_ptr<const effects::ParticleSet> uploaded;  //!< held, so its identity stays unique
  std::int64_t count = 0;
};

}  // namespace

struct GrainGl::Impl {
  GlProgram shader, particles;
  unsigned empty_vao = 0;
  std::map<std::size_t, Buffers> buffers;  //!< per grain effect (GrainFrame::effect)
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
    glUniform2f(loc("u_viewport"), static_cast<float>(width), static_cast<float>(height));
    glBindVertexArray(empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++stats.shader_draws;
  }

  Buffers& upload(const effects::GrainFrame& f) {
    Buffers& b = buffers[f.effect];
    if (!b.vao) {
      glGenVertexArrays(1, &b.vao);
      glGenBuffers(1, &b.vbo);
      glBindVertexArray(b.vao);
      glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
      const GLsizei stride = kFloatsPerParticle * sizeof(float);
      const std::array<int, 4> sizes{3, 3, 4, 2};
      std::size_t offset = 0;
      for (unsigned a = 0; a < sizes.size(); ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset * sizeof(float)));
        glVertexAttribDivisor(a, 1);
        offset += static_cast<std::size_t>(sizes[a]);
      }
    }
    if (b.uploaded != f.particles) {
      const auto& ps = f.particles->particles;
      std::vector<float> data;
      data.reserve(ps.size() * kFloatsPerParticle);
      for (const effects::GrainParticle& p : ps) {
        for (int a = 0; a < 3; ++a) data.push_back(static_cast<float>(p.centre[a]));
        for (int a = 0; a < 3; ++a) data.push_back(static_cast<float>(p.extent[a]));
        for (int a = 0; a < 4; ++a) data.push_back(static_cast<float>(p.rotation[a]));
        data.push_back(static_cast<float>(p.brightness));
        data.push_back(static_cast<float>(p.opacity));
      }
      glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)),
                   data.data(), GL_STREAM_DRAW);
      b.uploaded = f.particles;
      b.count = static_cast<std::int64_t>(ps.size());
      ++stats.particle_uploads;
    }
    return b;
  }

  void draw_particles(const RenderView& view, int width, int height, const effects::GrainFrame& f) {
    if (!f.particles || f.particles->particles.empty()) return;
    Buffers& b = upload(f);
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
    glBindVertexArray(b.vao);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(b.count));
    ++stats.particle_draws;
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
  for (auto& [_, b] : impl_->buffers) {
    glDeleteBuffers(1, &b.vbo);
    glDeleteVertexArrays(1, &b.vao);
  }
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
