/// @file
/// @brief FlareGl: one quad per flare element, additive blending into the float eye buffer.
#include "xr/render/flare_gl.h"

#include <epoxy/gl.h>

#include "effects/flare_shaders.h"
#include "xr/render/gl_program.h"

namespace vdfx::xr {

namespace {

// The headset plane sits a few centimetres from the eyes (0.01 m at the least): the near plane
// must be closer. Depth is not tested, so an infinite far plane only avoids clipping at 10 km.
constexpr double kNear = 1e-3;

}  // namespace

struct FlareGl::Impl {
  GlProgram program;
  unsigned vao = 0;
  std::vector<effects::FlareLayout> layouts;
};

FlareGl::FlareGl() : impl_(std::make_unique<Impl>()) {
  impl_->program =
      GlProgram::build("flare", effects::flare_vertex_source(), effects::flare_fragment_source());
  glGenVertexArrays(1, &impl_->vao);
}

FlareGl::~FlareGl() {
  if (impl_ && impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
}

void FlareGl::set_layouts(std::vector<effects::FlareLayout> layouts) {
  impl_->layouts = std::move(layouts);
}

const std::vector<effects::FlareLayout>& FlareGl::layouts() const {
  return impl_->layouts;
}

void FlareGl::draw(const RenderView& view, int, int width, int height) {
  Impl& m = *impl_;
  if (m.layouts.empty()) return;
  // Positions are sent relative to the eye, so the rotation alone maps them into eye space and
  // floats keep sub-millimetre precision at the directional style's 100 m.
  Eigen::Matrix4d rot = Eigen::Matrix4d::Identity();
  rot.topLeftCorner<3, 3>() = view.orientation.transpose();
  const Eigen::Matrix4f view_proj = (view.projection(kNear, 0.0) * rot).cast<float>();
  m.program.use();
  glBindVertexArray(m.vao);
  glUniformMatrix4fv(m.program.uniform("u_view_proj"), 1, GL_FALSE, view_proj.data());
  const Eigen::Matrix3f eye_rot = view.orientation.cast<float>();
  glUniformMatrix3fv(m.program.uniform("u_eye_rot"), 1, GL_FALSE, eye_rot.data());
  glUniform4f(m.program.uniform("u_tan"), static_cast<float>(view.tan_left),
              static_cast<float>(view.tan_right), static_cast<float>(view.tan_down),
              static_cast<float>(view.tan_up));
  glUniform2f(m.program.uniform("u_size"), static_cast<float>(width), static_cast<float>(height));
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);  // light adds to the image under it
  const auto vec3 = [&](const char* name, const Eigen::Vector3d& v) {
    glUniform3f(m.program.uniform(name), static_cast<float>(v.x()), static_cast<float>(v.y()),
                static_cast<float>(v.z()));
  };
  for (const effects::FlareLayout& l : m.layouts) {
    vec3("u_axis_u", l.axis_u);
    vec3("u_axis_v", l.axis_v);
    for (const effects::FlareElement& e : l.elements) {
      const double support = effects::element_support(e);
      vec3("u_centre", e.centre - view.position);
      vec3("u_colour", e.colour);
      glUniform1f(m.program.uniform("u_extent"), static_cast<float>(support * e.radius));
      glUniform1f(m.program.uniform("u_support"), static_cast<float>(support));
      glUniform1i(m.program.uniform("u_shape"), static_cast<int>(e.shape));
      glUniform1f(m.program.uniform("u_chroma"), static_cast<float>(e.chroma));
      glDrawArrays(GL_TRIANGLES, 0, 6);
    }
  }
  glDisable(GL_BLEND);
}

}  // namespace vdfx::xr
