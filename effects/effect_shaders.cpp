/// @file
/// @brief GLSL of the effect stack; formulas are the contract's effect table.
#include "effects/effect_shaders.h"

#include <tuple>

#include "effects/glsl_common.h"

namespace vdfx::effects {

unsigned non_neutral_mask(const StackParams& p) {
  unsigned m = 0;
  for (int i = 0; i < kEffectCount; ++i) {
    const auto t = static_cast<EffectType>(i);
    if (!p.is_neutral(t)) m |= shader_bit(t);
  }
  return m;
}

bool StackShader::operator<(const StackShader& o) const {
  return std::tie(mask, blur, per_pixel, levels) < std::tie(o.mask, o.blur, o.per_pixel, o.levels);
}

std::string blur_1d_fragment_source() {
  return R"(out vec4 frag;
uniform sampler2D u_src;
uniform vec2 u_dir;          // (1, 0) horizontal, (0, 1) vertical, in texels
uniform sampler2D u_taps;    // texel k: (offset in texels, weight) of a symmetric pair
uniform int u_tap_count;
uniform float u_centre_weight;
void main() {
  vec2 texel = 1.0 / vec2(textureSize(u_src, 0));
  vec2 p = gl_FragCoord.xy * texel;
  vec3 acc = u_centre_weight * texture(u_src, p).rgb;
  for (int k = 0; k < u_tap_count; ++k) {
    vec2 t = texelFetch(u_taps, ivec2(k, 0), 0).xy;
    vec2 d = t.x * u_dir * texel;
    acc += t.y * (texture(u_src, p + d).rgb + texture(u_src, p - d).rgb);
  }
  frag = vec4(acc, 1.0);
}
)";
}

std::string downsample_fragment_source() {
  return R"(out vec4 frag;
uniform sampler2D u_src;
void main() {
  // [1 3 3 1] / 8 per axis around source coordinate 2 x: the pairs (1, 3) and (3, 1) are one
  // bilinear fetch each, 0.75 source pixels from the centre.
  vec2 texel = 1.0 / vec2(textureSize(u_src, 0));
  vec2 c = 2.0 * gl_FragCoord.xy;
  vec3 acc = texture(u_src, (c + vec2(-0.75, -0.75)) * texel).rgb +
             texture(u_src, (c + vec2(0.75, -0.75)) * texel).rgb +
             texture(u_src, (c + vec2(-0.75, 0.75)) * texel).rgb +
             texture(u_src, (c + vec2(0.75, 0.75)) * texel).rgb;
  frag = vec4(0.25 * acc, 1.0);
}
)";
}

namespace {

// The blur-level lookup of a Levels variant: one sampler per level (a per-pixel index may not
// select from a sampler array), so the switch names each one.
std::string level_function(int levels) {
  std::string s;
  for (int j = 1; j <= levels; ++j) s += "uniform sampler2D u_level" + std::to_string(j) + ";\n";
  s += "uniform float u_level_scale[" + std::to_string(levels) + "];\n";
  s += "vec3 blur_level(int j, vec2 p) {\n  switch (j) {\n";
  for (int j = 1; j <= levels; ++j) {
    const std::string n = "u_level" + std::to_string(j), k = std::to_string(j - 1);
    s += "    case " + std::to_string(j) + ": return textureLod(" + n + ", p / (u_level_scale[" +
         k + "] * vec2(textureSize(" + n + ", 0))), 0.0).rgb;\n";
  }
  s += "  }\n  return texelFetch(u_src, ivec2(p), 0).rgb;\n}\n";
  return s;
}

// The stack's fragment shader in parts, which stack_fragment_source joins in this order around
// what it writes itself (the variant's #defines, the Levels variant's lookup).

// The source's uniforms and each blur mode's (the Levels mode's lookup follows, then kStackParams
// closes the #if).
constexpr const char* kStackBlurUniforms = R"(out vec4 frag;
uniform sampler2D u_src;
uniform int u_margin;  // the source is larger than the target by this many pixels on each side
uniform vec2 u_centre_tan;
#if BLUR_MODE == 1
uniform sampler2D u_taps;
uniform int u_tap_count;
uniform float u_centre_weight;
#elif BLUR_MODE == 2
uniform sampler2D u_blurred;
uniform float u_blurred_scale;
#elif BLUR_MODE == 3
uniform float u_tau1_deg;
uniform float u_level_log2r;  // log2 of the ratio between successive level sigmas
)";

// The effects' parameters, then main()'s first part: this pixel's ray, source pixel and
// parameters (per-pixel grids or one value each).
constexpr const char* kStackParams = R"(#endif
#if PER_PIXEL
uniform sampler2D u_grid0;  // tint gain r, g, b; exposure stops
uniform sampler2D u_grid1;  // saturation, contrast, vignette radius, falloff (radians)
uniform sampler2D u_grid2;  // blur sigma (degrees)
uniform mat3 u_rot;         // eye -> world
#else
uniform vec3 u_tint;
uniform float u_exposure_gain;
uniform float u_saturation;
uniform float u_contrast;
uniform vec2 u_vignette;
#endif
void main() {
  vec3 ray = pinhole_ray();
  vec2 pc = gl_FragCoord.xy + vec2(float(u_margin));  // this pixel's centre in the source
#if PER_PIXEL
  // This pixel's parameters: the grid along its own world ray (t = 1 - v, gl_texture.h); the
  // grid textures repeat in s (azimuth wraps) and clamp in t.
  vec3 d = u_rot * ray;
  vec2 uv = equirect_uv(d);
  vec4 g0 = textureLod(u_grid0, uv, 0.0);
  vec4 g1 = textureLod(u_grid1, uv, 0.0);
  // Bilinear gains are renormalised (contract: tint never changes brightness).
  vec3 tint = g0.rgb / dot(g0.rgb, vec3(0.25, 0.5, 0.25));
  float exposure_gain = exp2(g0.a);
  float saturation = g1.r, contrast = g1.g;
  vec2 vignette = g1.ba;
#else
  vec3 tint = u_tint;
  float exposure_gain = u_exposure_gain;
  float saturation = u_saturation, contrast = u_contrast;
  vec2 vignette = u_vignette;
#endif
)";

// main(), then: the blur mode's colour of this pixel (or the plain source's).
constexpr const char* kStackBlur = R"(#if BLUR_MODE == 1
  // Vertical half of the separable Gaussian (the horizontal half ran in the pass before).
  vec2 texel = 1.0 / vec2(textureSize(u_src, 0));
  vec2 q0 = pc * texel;
  vec3 c = u_centre_weight * texture(u_src, q0).rgb;
  for (int k = 0; k < u_tap_count; ++k) {
    vec2 t = texelFetch(u_taps, ivec2(k, 0), 0).xy;
    vec2 dd = vec2(0.0, t.x * texel.y);
    c += t.y * (texture(u_src, q0 + dd).rgb + texture(u_src, q0 - dd).rgb);
  }
#elif BLUR_MODE == 2
  vec3 c = textureLod(u_blurred, pc / (u_blurred_scale * vec2(textureSize(u_blurred, 0))), 0.0).rgb;
#elif BLUR_MODE == 3
  // Mix the two levels around this pixel's sigma s with weights that give the mixture the
  // variance s^2 (levels tau_j and r tau_j: w = (s^2 - tau_j^2) / ((r^2 - 1) tau_j^2)).
  float s = textureLod(u_grid2, uv, 0.0).r;
  vec3 c = texelFetch(u_src, ivec2(pc), 0).rgb;
  if (s >= u_tau1_deg * exp2(float(LEVELS - 1) * u_level_log2r)) {
    c = blur_level(LEVELS, pc);
  } else if (s >= u_tau1_deg) {
    int j = min(1 + int(floor(log2(s / u_tau1_deg) / u_level_log2r)), LEVELS - 1);
    float tj = u_tau1_deg * exp2(float(j - 1) * u_level_log2r);
    float r2 = exp2(2.0 * u_level_log2r);
    float w = clamp((s * s - tj * tj) / ((r2 - 1.0) * tj * tj), 0.0, 1.0);
    c = mix(blur_level(j, pc), blur_level(j + 1, pc), w);
  } else if (s > 0.0) {
    c = mix(c, blur_level(1, pc), (s * s) / (u_tau1_deg * u_tau1_deg));
  }
#else
  vec3 c = texelFetch(u_src, ivec2(pc), 0).rgb;
#endif
)";

// main(), last: the colour effects in the contract's order, and the output.
constexpr const char* kStackGrade = R"(#if HAS_TINT
  c *= tint;
#endif
#if HAS_EXPOSURE
  c *= exposure_gain;
#endif
#if HAS_SATURATION
  float y = dot(c, vec3(0.25, 0.5, 0.25));
  c = vec3(y) + saturation * (c - vec3(y));
#endif
#if HAS_CONTRAST
  c = vec3(0.5) + contrast * (c - vec3(0.5));
#endif
#if HAS_VIGNETTE
  // d: angle between this pixel's ray and the eye's optical axis (atan2 form, accurate near 0).
  vec3 axis = vec3(u_centre_tan, -1.0);
  float dv = atan(length(cross(ray, axis)), dot(ray, axis));
  float f = clamp(1.0 - (dv - vignette.x) / vignette.y, 0.0, 1.0);
  c *= f;
#endif
  frag = vec4(c, 1.0);
}
)";

}  // namespace

std::string stack_fragment_source(const StackShader& v) {
  using B = StackShader::Blur;
  std::string s;
  const auto def = [&](const char* name, bool on) {
    s += std::string("#define ") + name + (on ? " 1\n" : " 0\n");
  };
  const auto has = [&](EffectType t) { return (v.mask & shader_bit(t)) != 0; };
  def("HAS_TINT", has(EffectType::Tint));
  def("HAS_EXPOSURE", has(EffectType::Exposure));
  def("HAS_SATURATION", has(EffectType::Saturation));
  def("HAS_CONTRAST", has(EffectType::Contrast));
  def("HAS_VIGNETTE", has(EffectType::Vignette));
  def("PER_PIXEL", v.per_pixel);
  s += "#define BLUR_MODE " + std::to_string(static_cast<int>(v.blur)) + "\n";
  s += glsl::kConstants;
  s += glsl::kPinhole;
  s += glsl::kEquirect;
  s += kStackBlurUniforms;
  if (v.blur == B::Levels) s += level_function(v.levels);
  s += "#define LEVELS " + std::to_string(v.blur == B::Levels ? v.levels : 0) + "\n";
  s += kStackParams;
  s += kStackBlur;
  s += kStackGrade;
  return s;
}

std::string stack_fragment_source(unsigned mask) {
  StackShader v;
  v.mask = mask;
  v.blur = (mask & shader_bit(EffectType::Blur)) ? StackShader::Blur::FusedVertical
                                                 : StackShader::Blur::None;
  return stack_fragment_source(v);
}

}  // namespace vdfx::effects
