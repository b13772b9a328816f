/// @file
/// @brief Flare GLSL, generated with the C++ reference's constants.
#include "effects/flare_shaders.h"

#include <cstdio>

#include "effects/flare_layout.h"
#include "effects/glsl_common.h"

namespace vdfx::effects {

std::string flare_vertex_source() {
  return R"(
uniform mat4 u_view_proj;
uniform vec3 u_centre;
uniform vec3 u_axis_u;
uniform vec3 u_axis_v;
uniform float u_extent;
void main() {
  const vec2 corners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0),
                                  vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));
  vec2 c = corners[gl_VertexID];
  vec3 p = u_centre + u_extent * (c.x * u_axis_u + c.y * u_axis_v);
  gl_Position = u_view_proj * vec4(p, 1.0);
}
)";
}

std::string flare_fragment_source() {
  char constants[160];
  // %.17g: the shader's constants are the doubles of flare_layout.h, rounded once to float.
  std::snprintf(constants, sizeof constants,
                "const float RIM = %.17g;\nconst float FILL = %.17g;\n", kRingRimWidth, kRingFill);
  return std::string(constants) + glsl::kPinhole + R"(
out vec4 frag;
uniform mat3 u_eye_rot;  // the eye's rotation, eye -> world
uniform vec3 u_centre;
uniform vec3 u_axis_u;
uniform vec3 u_axis_v;
uniform float u_extent;
uniform float u_support;
uniform int u_shape;
uniform vec3 u_colour;
uniform float u_chroma;
float bump(float x) {
  float a = 1.0 - x * x;
  return a > 0.0 ? a * a : 0.0;
}
float ring_channel(float rho) {
  return bump((rho - 1.0) / RIM) + FILL * (1.0 - smoothstep(1.0 - RIM, 1.0, rho));
}
void main() {
  // This fragment's own ray meets the element's plane, as the CPU reference's flare_at_ray:
  // world axes, the eye at the origin. Not an interpolated varying: where a rasteriser snaps the
  // quad's corners to its sub-pixel grid then moves no ring (a ring a few pixels wide has a rim
  // of a fraction of a pixel).
  vec3 d = u_eye_rot * pinhole_ray();
  vec3 n = cross(u_axis_u, u_axis_v);
  float dn = dot(n, d);
  if (dn == 0.0) discard;
  float t = dot(n, u_centre) / dn;
  if (!(t > 0.0)) discard;
  vec3 q = t * d - u_centre;
  float rho = length(vec2(dot(q, u_axis_u), dot(q, u_axis_v))) * (u_support / u_extent);
  vec3 p;
  if (u_shape == 0) {
    float a = bump(rho);
    p = vec3(a * a);
  } else {
    // Chromatic scattering: red drawn at (1 + chroma) radii, blue at (1 - chroma).
    p = vec3(ring_channel(rho / (1.0 + u_chroma)), ring_channel(rho),
             ring_channel(rho / (1.0 - u_chroma)));
  }
  frag = vec4(u_colour * p, 0.0);
}
)";
}

}  // namespace vdfx::effects
