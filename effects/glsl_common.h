/// @file
/// @brief GLSL that several programs share, written once (strings: effects/ never links GL).
///
/// Every program that needs one of these concatenates it in front of its own source (the
/// program builder, xr/render/gl_program.h, prepends only the target's prelude below), so pi, the
/// pinhole ray of a fragment and the ray -> equirect mapping have one definition for the video
/// layer, the effect stack, the lens passes and grain. The formulas are the CPU reference's
/// (effects/view_camera.h for the pinhole, effects/coords.h for the equirect mapping).
#pragma once

namespace vdfx::effects::glsl {

/// The two targets every source here and in the effects' shader files compiles for: desktop GL
/// (the editor, `vdfx render --gpu`) and GLSL ES 3.00 (WebGL2, the page of `vdfx publish`). A
/// source carries no #version line; its target's prelude goes in front of it. Where the targets
/// differ (WebGL2 has no dual-source blending) a source tests `#ifdef GL_ES`, which only an ES
/// compiler defines.
enum class Target { Desktop, Es300 };

/// `#version` and, for ES, default precisions: highp everywhere, since the effects' float
/// arithmetic is held to the CPU reference (ES's default sampler precision is lowp).
inline constexpr const char* kDesktopPrelude = "#version 430 core\n";
inline constexpr const char* kEs300Prelude = R"(#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
)";
inline constexpr const char* prelude(Target t) {
  return t == Target::Desktop ? kDesktopPrelude : kEs300Prelude;
}

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
/// world ray d, t = 1 - v because textures start at the bottom row (xr/render/gl_texture.h). Needs
/// kConstants.
inline constexpr const char* kEquirect = R"(vec2 equirect_uv(vec3 d) {
  return vec2(0.5 + atan(d.x, -d.z) / (2.0 * PI), 0.5 + atan(d.y, length(d.xz)) / PI);
}
)";

/// The vertex shader of every full-screen pass: one triangle covering the viewport, no vertex
/// buffer (gl_VertexID 0..2); `v_uv` runs 0..1 across the viewport, (0, 0) at the bottom-left.
inline constexpr const char* kFullscreenVertex = R"(out vec2 v_uv;
void main() {
  // Vertices (-1,-1), (3,-1), (-1,3): one triangle that covers the viewport.
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

}  // namespace vdfx::effects::glsl
