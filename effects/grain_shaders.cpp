/// @file
/// @brief GLSL of the grain layer: the Perlin noise (as effects/perlin_noise.cpp), the shader
/// styles (as effects/grain_render.cpp) and the particle quads.
#include "effects/grain_shaders.h"

#include "effects/glsl_common.h"

namespace vdfx::effects {
namespace {

// Improved noise, operation for operation as PerlinNoise::operator().
constexpr const char* kNoise = R"(
uniform ivec4 u_perm[64];
int perm_at(int i) {
  i &= 255;
  return u_perm[i >> 2][i & 3];
}
const vec3 kGrad[16] = vec3[16](
    vec3(1, 1, 0), vec3(-1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0),
    vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
    vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, 1, -1), vec3(0, -1, -1),
    vec3(1, 1, 0), vec3(0, -1, 1), vec3(-1, 1, 0), vec3(0, -1, -1));
float fade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
float lerp1(float t, float a, float b) { return a + t * (b - a); }
float corner(int h, float ox, float oy, float oz) {
  vec3 g = kGrad[h & 15];
  return g.x * ox + g.y * oy + g.z * oz;
}
float perlin(vec3 p) {
  vec3 f = floor(p);
  int X = int(f.x) & 255, Y = int(f.y) & 255, Z = int(f.z) & 255;
  float dx = p.x - f.x, dy = p.y - f.y, dz = p.z - f.z;
  float u = fade(dx), v = fade(dy), w = fade(dz);
  int a = perm_at(X) + Y, b = perm_at(X + 1) + Y;
  int aa = perm_at(a) + Z, ab = perm_at(a + 1) + Z, ba = perm_at(b) + Z, bb = perm_at(b + 1) + Z;
  float x1 = dx - 1.0, y1 = dy - 1.0, z1 = dz - 1.0;
  float n000 = corner(perm_at(aa), dx, dy, dz), n100 = corner(perm_at(ba), x1, dy, dz);
  float n010 = corner(perm_at(ab), dx, y1, dz), n110 = corner(perm_at(bb), x1, y1, dz);
  float n001 = corner(perm_at(aa + 1), dx, dy, z1), n101 = corner(perm_at(ba + 1), x1, dy, z1);
  float n011 = corner(perm_at(ab + 1), dx, y1, z1), n111 = corner(perm_at(bb + 1), x1, y1, z1);
  float near_ = lerp1(v, lerp1(u, n000, n100), lerp1(u, n010, n110));
  float far_ = lerp1(v, lerp1(u, n001, n101), lerp1(u, n011, n111));
  return lerp1(w, near_, far_);
}
)";

// How a grain fragment modulates the eye colour C into s floor + C (1 + s). Desktop GL: dual-source
// blending (ONE, SRC1_COLOR), out = frag + dst * frag_scale. WebGL2 has no dual-source blending,
// but the scale is one number for every channel: it travels in alpha and blends (ONE, SRC_ALPHA)
// into a float target, whose blend factors are unclamped.
constexpr const char* kGrainOutput = R"(
uniform float u_floor;
#ifdef GL_ES
out vec4 frag;
void grain_out(float s) { frag = vec4(vec3(s * u_floor), 1.0 + s); }
#else
layout(location = 0, index = 0) out vec4 frag;
layout(location = 0, index = 1) out vec4 frag_scale;
void grain_out(float s) {
  frag = vec4(vec3(s * u_floor), 0.0);
  frag_scale = vec4(vec3(1.0 + s), 1.0);
}
#endif
)";

constexpr const char* kShaderStyles = R"(
uniform int u_style;
uniform mat3 u_eye_to_grain;
uniform vec3 u_eye;
uniform float u_distance;
uniform float u_inv_cell;
uniform vec3 u_offset1;
uniform vec3 u_offset2;
uniform float u_octave2;
uniform float u_gain;
void main() {
  // The pinhole's tangent (glsl_common.h) written out operation for operation as
  // effects/grain_render.cpp does in float, which the GL-vs-CPU tests hold it to.
  float tx = u_tan.x + (gl_FragCoord.x / u_size.x) * (u_tan.y - u_tan.x);
  float ty = u_tan.z + (gl_FragCoord.y / u_size.y) * (u_tan.w - u_tan.z);
  vec3 d = u_eye_to_grain[0] * tx + u_eye_to_grain[1] * ty - u_eye_to_grain[2];
  d = d * (1.0 / sqrt(dot(d, d)));
  vec3 e = u_eye;
  float pixel_rad = (u_tan.y - u_tan.x) / u_size.x / sqrt(1.0 + tx * tx + ty * ty);
  vec3 lattice;
  float cells_per_pixel;
  if (u_style == 0) {
    if (!(d.z < 0.0)) discard;
    float s = (-u_distance - e.z) / d.z;
    vec3 q = e + d * s;
    lattice = vec3(q.x * u_inv_cell, q.y * u_inv_cell, 0.0);
    cells_per_pixel = s * pixel_rad / -d.z * u_inv_cell;
  } else {
    float b = dot(d, e), c = dot(e, e) - u_distance * u_distance;
    float disc = b * b - c;
    if (!(disc >= 0.0)) discard;
    float s = -b + sqrt(disc);
    lattice = (e + d * s) * u_inv_cell;
    cells_per_pixel = s * pixel_rad * u_inv_cell;
  }
  float w1 = clamp(2.0 - 2.0 * cells_per_pixel, 0.0, 1.0);
  float w2 = clamp(2.0 - 4.0 * cells_per_pixel, 0.0, 1.0);
  vec3 p1 = lattice + u_offset1;
  vec3 p2 = lattice * 2.0 + u_offset2;
  float n1 = w1 > 0.0 ? perlin(p1) : 0.0;
  float n2 = w2 > 0.0 ? perlin(p2) : 0.0;
  float g = w1 * n1 + u_octave2 * w2 * n2;
  grain_out(max(-1.0, u_gain * g));
}
)";

// The particle of gl_InstanceID, generated here as effects::grain_particle defines it (draw j of
// particle i: unit_uniform(hash32_draw(key, i, j)), the draws numbered as effects::ParticleDraw),
// in float; the C++ clamp into the region is left out (rounding moves a point by about 1e-7 of
// its radius). Nothing is uploaded per refresh: only the key changes.
constexpr const char* kParticleStream = R"(
uniform uint u_key;
uniform int u_cloud;          // 0: object_cloud, 1: free_cloud
uniform uint u_shell_threshold;
uniform vec4 u_radii;         // object_cloud: shell r0, ln(r1 / r0); surrounding r0, ln(r1 / r0)
uniform vec2 u_cylinder;      // free_cloud: radius, height
uniform vec2 u_extent_range;  // min, max - min, metres at size 1
uniform float u_min_opacity;
const float TWO_PI = 6.28318530717959;
uint hash32(uint x) {  // lowbias32, as effects::hash32
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}
uint draw_bits(uint i, uint j) { return hash32(hash32(u_key ^ i) ^ j); }
float draw(uint i, uint j) { return float(draw_bits(i, j) >> 8u) * (1.0 / 16777216.0); }
vec3 particle_centre(uint i) {
  float u0 = draw(i, 1u), u1 = draw(i, 2u), u2 = draw(i, 3u);
  if (u_cloud == 1) {
    float rho = u_cylinder.x * sqrt(u0), phi = TWO_PI * u1;
    return vec3(rho * cos(phi), (u2 - 0.5) * u_cylinder.y, rho * sin(phi));
  }
  vec2 region = (draw_bits(i, 0u) >> 8u) >= u_shell_threshold ? u_radii.zw : u_radii.xy;
  float r = region.x * exp((1.0 - u0) * region.y);
  float z = 1.0 - 2.0 * u1, phi = TWO_PI * u2;
  float s = sqrt(max(0.0, 1.0 - z * z));
  return r * vec3(s * cos(phi), z, s * sin(phi));
}
vec4 particle_rotation(uint i) {  // Shoemake's uniform quaternion (x, y, z, w)
  float u1 = draw(i, 7u), u2 = TWO_PI * draw(i, 8u), u3 = TWO_PI * draw(i, 9u);
  float a = sqrt(1.0 - u1), b = sqrt(u1);
  return vec4(a * sin(u2), a * cos(u2), b * sin(u3), b * cos(u3));
}
)";

constexpr const char* kParticleVertex = R"(
uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform vec3 u_eye_up;
uniform vec3 u_eye_right;
uniform float u_size;
uniform float u_intensity;
uniform float u_px_per_tan;
uniform float u_near_start;
uniform float u_near_end;
uniform float u_min_radius_px;
uniform float u_max_radius_rad;
out vec3 v_point;
flat out vec3 v_centre;
flat out vec3 v_semi;
flat out vec4 v_rotation;
flat out vec2 v_shade;
void main() {
  uint id = uint(gl_InstanceID);
  vec3 a_centre = particle_centre(id);
  vec3 a_extent = u_extent_range.x + u_extent_range.y * vec3(draw(id, 4u), draw(id, 5u), draw(id, 6u));
  vec4 a_rotation = particle_rotation(id);
  vec2 a_shade = vec2(draw(id, 10u), u_min_opacity + (1.0 - u_min_opacity) * draw(id, 11u));
  vec3 semi = 0.5 * a_extent * u_size;
  float r = max(semi.x, max(semi.y, semi.z));
  vec3 to = a_centre - u_eye;
  float dist = length(to);
  float alpha = a_shade.y * u_intensity * smoothstep(u_near_start, u_near_end, dist);
  // A grain seen larger than u_max_radius_rad (a particle close to the eye) keeps the coverage of
  // one that size: it fades as (max / radius)^2 instead of showing as a flake.
  float radius_rad = r / dist;
  if (radius_rad > u_max_radius_rad) alpha *= (u_max_radius_rad / radius_rad) * (u_max_radius_rad / radius_rad);
  // Coverage-preserving minimum footprint: every semi-axis under u_min_radius_px grows to it and
  // the particle thins by the volume ratio to the 2/3 (its projected area's, on average over
  // orientations), so a thin or sub-pixel grain covers whole pixels the same way in both eyes
  // instead of hitting or missing pixel centres by its sampling phase.
  float min_semi = u_min_radius_px / u_px_per_tan * dist;
  vec3 grown = max(semi, vec3(min_semi));
  alpha *= pow((semi.x * semi.y * semi.z) / (grown.x * grown.y * grown.z), 2.0 / 3.0);
  semi = grown;
  r = max(r, min_semi);
  v_centre = a_centre;
  v_semi = semi;
  v_rotation = a_rotation;
  // Modulation amplitude: brightness 0 darkens, 1 brightens, 0.5 leaves the image as it is.
  v_shade = vec2(2.0 * a_shade.x - 1.0, alpha);
  if (!(alpha > 0.0) || dist <= 1.05 * r) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
    v_point = a_centre;
    return;
  }
  // A quad perpendicular to the line of sight, large enough to hold the bounding sphere's
  // silhouette (half-size r d / sqrt(d^2 - r^2) at the centre's distance).
  vec3 w = to / dist;
  vec3 side = cross(w, u_eye_up);
  if (dot(side, side) < 1e-12) side = u_eye_right;
  side = normalize(side);
  vec3 up = cross(side, w);
  float hs = r * dist / sqrt(dist * dist - r * r);
  vec2 c = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vec3 p = a_centre + hs * (c.x * side + c.y * up);
  v_point = p;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
)";

constexpr const char* kParticleFragment = R"(
in vec3 v_point;
flat in vec3 v_centre;
flat in vec3 v_semi;
flat in vec4 v_rotation;
flat in vec2 v_shade;
uniform vec3 u_eye;
// Rotates by the inverse of the unit quaternion q = (x, y, z, w).
vec3 rotate_inverse(vec4 q, vec3 v) {
  vec3 u = -q.xyz;
  return v + 2.0 * cross(u, cross(u, v) + q.w * v);
}
void main() {
  vec3 o = rotate_inverse(v_rotation, u_eye - v_centre) / v_semi;
  vec3 d = rotate_inverse(v_rotation, v_point - u_eye) / v_semi;
  float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 1.0;
  float disc = b * b - a * c;
  if (!(disc > 0.0)) discard;
  grain_out(max(-1.0, v_shade.x * v_shade.y * (disc / a)));
}
)";

}  // namespace

std::string grain_shader_fragment_source() {
  return std::string(glsl::kPinhole) + kNoise + kGrainOutput + kShaderStyles;
}
std::string grain_particle_vertex_source() {
  return std::string(kParticleStream) + kParticleVertex;
}
std::string grain_particle_fragment_source() {
  return std::string(kGrainOutput) + kParticleFragment;
}

}  // namespace vdfx::effects
