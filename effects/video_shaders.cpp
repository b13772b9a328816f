/// @file
/// @brief The video layer's GLSL.
#include "effects/video_shaders.h"

#include "effects/glsl_common.h"

namespace vdfx::effects {
namespace {

constexpr const char* kFragment = R"(out vec4 frag;
uniform sampler2D u_equirect;
uniform mat3 u_rot;      // eye -> world
uniform int u_lod_mode;  // 0 analytic, 1 hardware derivatives, 2 base level, 3 footprint
uniform float u_max_aniso;  // footprint: the largest ratio of the axes resolved by taps
// Y'CbCr source (u_ycbcr = 1): planes uploaded top row first (v, not t), converted per sample.
uniform int u_ycbcr;
uniform sampler2D u_plane0, u_plane1, u_plane2;
uniform vec2 u_chroma_scale, u_chroma_offset;  // luma (u, v) -> chroma (u, v), siting included
uniform float u_code_scale;  // normalised texel -> code value (255 or 65535)
uniform mat3 u_m;            // code values -> R'G'B' (io/ycbcr.h)
uniform vec3 u_offset;
uniform float u_chroma_lod;  // level offset of the chroma planes: -log2 of their subsampling
// Degrees of azimuth the image spans (360, or 180 for VR180) and the fade inside a VR180 edge.
uniform float u_coverage;
uniform float u_edge;

// (d azimuth, d altitude) for a change e of the (unnormalised) ray d, as
// effects/pixel_footprint.cpp computes it (the pole axis within 1e-6 of a radian included).
vec2 angle_differential(vec3 d, vec3 e) {
  float h2 = dot(d.xz, d.xz);
  float min_h2 = 1e-12 * dot(d, d);
  if (h2 < min_h2) return vec2(length(e.xz) / sqrt(min_h2), 0.0);
  float h = sqrt(h2);
  float daz = (-d.z * e.x + d.x * e.z) / h2;
  float dh = (d.x * e.x + d.z * e.z) / h;
  float dalt = (h * e.y - d.y * dh) / (h2 + d.y * d.y);
  return vec2(daz, dalt);
}

// (du, dt) for a change e of the ray d; see video_layer.h for the formulas.
vec2 uv_differential(vec3 d, vec3 e) {
  return angle_differential(d, e) / vec2(2.0 * PI, PI);
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

// The video at (u, t), trilinear at level of detail `lod` (the chroma planes at their own level).
vec3 sample_video_lod(vec2 uv, float lod) {
  if (u_ycbcr == 0) return textureLod(u_equirect, uv, lod).rgb;
  vec2 p = vec2(uv.x, 1.0 - uv.y);
  vec2 c = p * u_chroma_scale + u_chroma_offset;
  float lc = lod + u_chroma_lod;
  vec3 codes = vec3(textureLod(u_plane0, p, lod).r, textureLod(u_plane1, c, lc).r,
                    textureLod(u_plane2, c, lc).r);
  return clamp(u_m * (codes * u_code_scale) + u_offset, 0.0, 1.0);
}

// The image's (u, t) of a world ray: VR180's u spans azimuth -90..90.
vec2 image_uv(vec3 d, float scale) {
  vec2 uv = equirect_uv(d);
  uv.x = 0.5 + (uv.x - 0.5) * scale;
  return uv;
}

// The pixel filtered over its footprint (effects/pixel_footprint.h, the same taps, weights and
// level): ray d at the pixel centre, ex and ey its change per pixel step in x and y.
vec3 footprint_sample(vec3 d, vec3 ex, vec3 ey, float scale) {
  vec2 size = vec2(u_ycbcr == 0 ? textureSize(u_equirect, 0) : textureSize(u_plane0, 0));
  float per_turn = size.x * scale;
  vec2 texels = vec2(per_turn / (2.0 * PI), size.y / PI);
  vec2 jx = angle_differential(d, ex) * texels, jy = angle_differential(d, ey) * texels;
  // Scaled to its largest entry first: near a pole J's squares would overflow a float.
  float big = max(max(abs(jx.x), abs(jx.y)), max(abs(jy.x), abs(jy.y)));
  float norm = big > 0.0 ? big : 1.0;
  jx /= norm;
  jy /= norm;
  float a = dot(jx, jx), b = dot(jx, jy), c = dot(jy, jy);
  float dev = length(vec2(0.5 * (a - c), b));
  float s1 = sqrt(0.5 * (a + c) + dev);
  float s2 = s1 > 0.0 ? abs(jx.x * jy.y - jy.x * jx.y) / s1 : 0.0;
  s1 = min(s1 * norm, per_turn);
  s2 = min(s2 * norm, s1);
  float theta = (b == 0.0 && a == c) ? 0.0 : 0.5 * atan(2.0 * b, a - c);
  float r = clamp(s1 / max(s2, 1.0), 1.0, max(u_max_aniso, 1.0));
  float spacing = 1.0 / r;
  int half_count = int(ceil(0.5 * (r - 1.0)));
  float lod = log2(max(max(s1 / r, s2), 1.0));
  vec3 step = spacing * (cos(theta) * ex + sin(theta) * ey);
  vec3 sum = vec3(0.0);
  for (int k = -half_count; k <= half_count; ++k) {
    float at = float(k) * spacing;
    float w = max(min(at + 0.5 * spacing, 0.5) - max(at - 0.5 * spacing, -0.5), 0.0);
    sum += w * sample_video_lod(image_uv(d + float(k) * step, scale), lod);
  }
  return sum;
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
  vec3 ex = u_rot[0] * ((u_tan.y - u_tan.x) / u_size.x);
  vec3 ey = u_rot[1] * ((u_tan.w - u_tan.z) / u_size.y);
  vec3 c;
  if (u_lod_mode == 3) {
    c = footprint_sample(d, ex, ey, scale);
  } else if (u_lod_mode == 0) {
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

// The reduction of one mip level into the next (effects/mip_chain.h): u_src's base level is the
// level above; each texel is the area average of the texels under it.
constexpr const char* kMipLevel = R"(out vec4 frag;
uniform sampler2D u_src;
void main() {
  ivec2 n = textureSize(u_src, 0);
  ivec2 m = max(n / 2, ivec2(1));
  ivec2 k = ivec2(gl_FragCoord.xy);
  vec2 span = vec2(n) / vec2(m);
  vec2 start = vec2(k) * span, end = vec2(k + 1) * span;
  ivec2 i0 = ivec2(floor(start)), i1 = ivec2(ceil(end)) - 1;
  vec4 acc = vec4(0.0);
  for (int y = i0.y; y <= i1.y; ++y) {
    float wy = (min(end.y, float(y + 1)) - max(start.y, float(y))) / span.y;
    if (wy <= 0.0) continue;
    for (int x = i0.x; x <= i1.x; ++x) {
      float wx = (min(end.x, float(x + 1)) - max(start.x, float(x))) / span.x;
      if (wx > 0.0) acc += (wx * wy) * texelFetch(u_src, min(ivec2(x, y), n - 1), 0);
    }
  }
  frag = acc;
}
)";

}  // namespace

std::string video_layer_fragment_source() {
  return std::string(glsl::kConstants) + glsl::kPinhole + glsl::kEquirect + kFragment;
}

std::string mip_level_fragment_source() {
  return kMipLevel;
}

}  // namespace vdfx::effects
