/// @file
/// @brief The video layer's GLSL.
#include "effects/video_shaders.h"

#include "effects/glsl_common.h"

namespace vdfx::effects {
namespace {

constexpr const char* kFragment = R"(out vec4 frag;
uniform sampler2D u_equirect;
uniform mat3 u_rot;      // eye -> world
uniform int u_lod_mode;  // 0 analytic, 1 hardware derivatives, 2 base level
// Y'CbCr source (u_ycbcr = 1): planes uploaded top row first (v, not t), converted per sample.
uniform int u_ycbcr;
uniform sampler2D u_plane0, u_plane1, u_plane2;
uniform vec2 u_chroma_scale, u_chroma_offset;  // luma (u, v) -> chroma (u, v), siting included
uniform float u_code_scale;  // normalised texel -> code value (255 or 65535)
uniform mat3 u_m;            // code values -> R'G'B' (io/ycbcr.h)
uniform vec3 u_offset;
// Degrees of azimuth the image spans (360, or 180 for VR180) and the fade inside a VR180 edge.
uniform float u_coverage;
uniform float u_edge;

// (du, dv) for a change e of the (unnormalised) ray d; see video_layer.h for the formulas.
vec2 uv_differential(vec3 d, vec3 e) {
  float h2 = max(dot(d.xz, d.xz), 1e-12);
  float h = sqrt(h2);
  float daz = (-d.z * e.x + d.x * e.z) / h2;
  float dh = (d.x * e.x + d.z * e.z) / h;
  float dalt = (h * e.y - d.y * dh) / (h2 + d.y * d.y);
  return vec2(daz / (2.0 * PI), dalt / PI);
}

// The video at (u, t) with screen-space gradients gx, gy (lod < 0: level 0 only).
vec3 sample_video(vec2 uv, vec2 gx, vec2 gy, bool base) {
  if (u_ycbcr == 0)
    return base ? textureLod(u_equirect, uv, 0.0).rgb : textureGrad(u_equirect, uv, gx, gy).rgb;
  vec2 p = vec2(uv.x, 1.0 - uv.y), px = vec2(gx.x, -gx.y), py = vec2(gy.x, -gy.y);
  vec2 c = p * u_chroma_scale + u_chroma_offset;
  vec3 codes;
  if (base) {
    codes = vec3(textureLod(u_plane0, p, 0.0).r, textureLod(u_plane1, c, 0.0).r, textureLod(u_plane2, c, 0.0).r);
  } else {
    vec2 cx = px * u_chroma_scale, cy = py * u_chroma_scale;
    codes = vec3(textureGrad(u_plane0, p, px, py).r, textureGrad(u_plane1, c, cx, cy).r,
                 textureGrad(u_plane2, c, cx, cy).r);
  }
  return clamp(u_m * (codes * u_code_scale) + u_offset, 0.0, 1.0);
}

void main() {
  vec3 d = u_rot * pinhole_ray();
  vec2 uv = equirect_uv(d);
  // VR180: the image's u spans azimuth -90..90 (twice the texels per degree); black outside,
  // fading over u_edge degrees inside the edge (effects/stereo_layout.h, coverage_weight).
  float scale = 360.0 / u_coverage;
  float weight = 1.0;
  if (u_coverage < 360.0) {
    float az = (uv.x - 0.5) * 360.0;
    weight = clamp((0.5 * u_coverage - abs(az)) / u_edge, 0.0, 1.0);
    uv.x = 0.5 + (uv.x - 0.5) * scale;
  }
  vec3 c;
  if (u_lod_mode == 0) {
    vec3 ex = u_rot[0] * ((u_tan.y - u_tan.x) / u_size.x);
    vec3 ey = u_rot[1] * ((u_tan.w - u_tan.z) / u_size.y);
    vec2 gx = uv_differential(d, ex), gy = uv_differential(d, ey);
    gx.x *= scale;
    gy.x *= scale;
    c = sample_video(uv, gx, gy, false);
  } else if (u_lod_mode == 1) {
    vec2 gx = dFdx(uv), gy = dFdy(uv);
    float u2 = fract(uv.x + 0.5);  // jumps at azimuth 0 instead of at the seam
    float gx2 = dFdx(u2), gy2 = dFdy(u2);
    if (abs(gx2) < abs(gx.x)) gx.x = gx2;
    if (abs(gy2) < abs(gy.x)) gy.x = gy2;
    c = sample_video(uv, gx, gy, false);
  } else {
    c = sample_video(uv, vec2(0.0), vec2(0.0), true);
  }
  frag = vec4(c * weight, 1.0);
}
)";

}  // namespace

std::string video_layer_fragment_source() {
  return std::string(glsl::kConstants) + glsl::kPinhole + glsl::kEquirect + kFragment;
}

}  // namespace vdfx::effects
