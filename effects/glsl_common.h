/// @file
/// @brief GLSL that several programs share, written once (strings: effects/ never links GL).
///
/// Every program that needs one of these concatenates it in front of its own source (the
/// program builder, xr/gl_program.h, prepends only the #version line), so pi, the pinhole ray
/// of a fragment and the ray -> equirect mapping have one definition for the video layer, the
/// effect stack, the lens passes and grain. The formulas are the CPU reference's
/// (effects/view_camera.h for the pinhole, effects/coords.h for the equirect mapping).
#pragma once

namespace vdfx::effects::glsl {

/// `PI` as a float constant.
inline constexpr const char* kConstants = R"(const float PI = 3.14159265358979;
)";

/// The pinhole of one eye buffer: its tangent rectangle (u_tan: left, right, down, up) and size
/// (u_size, pixels); `tan_at_fragment()` is this fragment's tangent (x right, y up) and
/// `pinhole_ray()` its view-space ray (unnormalised, -z forward).
inline constexpr const char* kPinhole = R"(uniform vec4 u_tan;   // left, right, down, up tangents
uniform vec2 u_size;  // target size in pixels
vec2 tan_at_fragment() {
  vec2 q = gl_FragCoord.xy / u_size;
  return vec2(mix(u_tan.x, u_tan.y, q.x), mix(u_tan.z, u_tan.w, q.y));
}
vec3 pinhole_ray() { return vec3(tan_at_fragment(), -1.0); }
)";

/// `equirect_uv(d)`: texture coordinates (u, t) of the equirect frame along the (unnormalised)
/// world ray d, t = 1 - v because textures start at the bottom row (xr/gl_texture.h). Needs
/// kConstants.
inline constexpr const char* kEquirect = R"(vec2 equirect_uv(vec3 d) {
  return vec2(0.5 + atan(d.x, -d.z) / (2.0 * PI), 0.5 + atan(d.y, length(d.xz)) / PI);
}
)";

}  // namespace vdfx::effects::glsl
