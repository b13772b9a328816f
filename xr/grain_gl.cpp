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

/// Grain frame (LOCAL axes, origin at the head) -> clip for one eye: OpenXR projection from the
/// eye's tangents with an infinite far plane (the surrounding volume reaches kilometres).
Eigen::Matrix4f view_projection(const RenderView& v, const Eigen::Vector3d& eye_in_grain) {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  const double w = v.tan_right - v.tan_left, h = v.tan_up - v.tan_down;
  p(0, 0) = 2.0 / w;
  p(0, 2) = (v.tan_right + v.tan_left) / w;
  p(1, 1) = 2.0 / h;
  p(1, 2) = (v.tan_up + v.tan_down) / h;
  p(2, 2) = -1.0;
  p(2, 3) = -2.0 * kNearM;
  p(3, 2) = -1.0;
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.topLeftCorner<3, 3>() = v.orientation.transpose();
  view.topRightCorner<3, 1>() = -v.orientation.transpose() * eye_in_grain;
  return (p * view).cast<float>();
}

class GrainLayerGlImpl final : public GrainLayerGl {
 public:
  GrainLayerGlImpl() {
    shader_ = GlProgram::build("grain_shader", fullscreen_vertex_source(),
                               effects::grain_shader_fragment_source());
    particles_ = GlProgram::build("grain_particles", effects::grain_particle_vertex_source(),
                                  effects::grain_particle_fragment_source());
    glGenVertexArrays(1, &empty_vao_);
    check_gl("GrainLayerGl::create");
  }
  ~GrainLayerGlImpl() override {
    for (auto& [_, b] : buffers_) {
      glDeleteBuffers(1, &b.vbo);
      glDeleteVertexArrays(1, &b.vao);
    }
    if (empty_vao_) glDeleteVertexArrays(1, &empty_vao_);
  }

  void render(const GlTarget& target, const RenderView& view,
              std::span<const effects::GrainFrame> layers) override {
    if (layers.empty()) return;
    target.bind();
    glEnable(GL_BLEND);
    // Premultiplied over on colour; the eye buffer's alpha is left as it was.
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    for (const effects::GrainFrame& f : layers) {
      if (!(f.params.intensity > 0.0)) continue;
      if (effects::is_volumetric(f.style)) draw_particles(target, view, f);
      else draw_shader(target, view, f);
    }
    glDisable(GL_BLEND);
    glBindVertexArray(0);
  }

  GrainLayerStats stats() const override { return stats_; }

 private:
  struct Buffers {
    unsigned vao = 0, vbo = 0;
    const effects::ParticleSet* uploaded = nullptr;
    std::int64_t count = 0;
  };

  void draw_shader(const GlTarget& target, const RenderView& view, const effects::GrainFrame& f) {
    const effects::ShaderGrainUniforms u =
        effects::shader_grain_uniforms(f, view.orientation, view.position, view.tangents());
    shader_.use();
    const auto loc = [&](const char* n) { return shader_.uniform(n); };
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
    glUniform4f(loc("u_tan"), u.tangents[0], u.tangents[1], u.tangents[2], u.tangents[3]);
    glUniform2f(loc("u_viewport"), static_cast<float>(target.width()),
                static_cast<float>(target.height()));
    glBindVertexArray(empty_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++stats_.shader_draws;
  }

  Buffers& upload(const effects::GrainFrame& f) {
    Buffers& b = buffers_[f.effect];
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
    if (b.uploaded != f.particles.get()) {
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
      b.uploaded = f.particles.get();
      b.count = static_cast<std::int64_t>(ps.size());
      held_[f.effect] = f.particles;  // keeps the pointer's identity meaningful
      ++stats_.particle_uploads;
    }
    return b;
  }

  void draw_particles(const GlTarget& target, const RenderView& view,
                      const effects::GrainFrame& f) {
    if (!f.particles || f.particles->particles.empty()) return;
    Buffers& b = upload(f);
    const Eigen::Vector3d eye = view.position - f.head.position;
    const Eigen::Matrix4f vp = view_projection(view, eye);
    const Eigen::Vector3f eye_f = eye.cast<float>();
    const Eigen::Vector3f up = view.orientation.col(1).cast<float>();
    const Eigen::Vector3f right = view.orientation.col(0).cast<float>();
    const double px_per_tan = std::min(target.width() / (view.tan_right - view.tan_left),
                                       target.height() / (view.tan_up - view.tan_down));
    particles_.use();
    const auto loc = [&](const char* n) { return particles_.uniform(n); };
    glUniformMatrix4fv(loc("u_view_proj"), 1, GL_FALSE, vp.data());
    glUniform3fv(loc("u_eye"), 1, eye_f.data());
    glUniform3fv(loc("u_eye_up"), 1, up.data());
    glUniform3fv(loc("u_eye_right"), 1, right.data());
    glUniform1f(loc("u_size"), static_cast<float>(f.params.size));
    glUniform1f(loc("u_intensity"), static_cast<float>(f.params.intensity));
    glUniform1f(loc("u_px_per_tan"), static_cast<float>(px_per_tan));
    glUniform1f(loc("u_near_start"), static_cast<float>(effects::kParticleNearFadeStartM));
    glUniform1f(loc("u_near_end"), static_cast<float>(effects::kParticleNearFadeEndM));
    glUniform1f(loc("u_min_radius_px"), static_cast<float>(effects::kParticleMinRadiusPx));
    glBindVertexArray(b.vao);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(b.count));
    ++stats_.particle_draws;
  }

  GlProgram shader_, particles_;
  unsigned empty_vao_ = 0;
  std::map<std::size_t, Buffers> buffers_;
  std::map<std::size_t, std::shared_ptr<const effects::ParticleSet>> held_;
  GrainLayerStats stats_;
};

}  // namespace

std::unique_ptr<GrainLayerGl> GrainLayerGl::create() { return std::make_unique<GrainLayerGlImpl>(); }

}  // namespace vdfx::xr
