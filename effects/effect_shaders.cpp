/// @file
/// @brief GLSL of the effect stack; formulas are the contract's effect table.
#include "effects/effect_shaders.h"

namespace vdfx::effects {

unsigned non_neutral_mask(const StackParams& p) {
  unsigned m = 0;
  for (int i = 0; i < kEffectCount; ++i) {
    const auto t = static_cast<EffectType>(i);
    if (!p.is_neutral(t)) m |= shader_bit(t);
  }
  return m;
}

std::string blur_horizontal_fragment_source() {
  return R"(out vec4 frag;
uniform sampler2D u_src;
uniform sampler2D u_taps;    // texel k: (offset in texels, weight) of a symmetric pair
uniform int u_tap_count;
uniform float u_centre_weight;
void main() {
  vec2 texel = 1.0 / vec2(textureSize(u_src, 0));
  vec2 p = gl_FragCoord.xy * texel;
  vec3 acc = u_centre_weight * texture(u_src, p).rgb;
  for (int k = 0; k < u_tap_count; ++k) {
    vec2 t = texelFetch(u_taps, ivec2(k, 0), 0).xy;
    vec2 d = vec2(t.x * texel.x, 0.0);
    acc += t.y * (texture(u_src, p + d).rgb + texture(u_src, p - d).rgb);
  }
  frag = vec4(acc, 1.0);
}
)";
}

std::string stack_fragment_source(unsigned mask) {
  std::string s;
  const auto def = [&](EffectType t, const char* name) {
    s += std::string("#define ") + name + ((mask & shader_bit(t)) ? " 1\n" : " 0\n");
  };
  def(EffectType::Blur, "HAS_BLUR");
  def(EffectType::Tint, "HAS_TINT");
  def(EffectType::Exposure, "HAS_EXPOSURE");
  def(EffectType::Saturation, "HAS_SATURATION");
  def(EffectType::Contrast, "HAS_CONTRAST");
  def(EffectType::Vignette, "HAS_VIGNETTE");
  s += R"(out vec4 frag;
uniform sampler2D u_src;
uniform int u_margin;  // the source is larger than the target by this many pixels on each side
#if HAS_BLUR
uniform sampler2D u_taps;
uniform int u_tap_count;
uniform float u_centre_weight;
#endif
#if HAS_TINT
uniform vec3 u_tint;
#endif
#if HAS_EXPOSURE
uniform float u_exposure_gain;
#endif
#if HAS_SATURATION
uniform float u_saturation;
#endif
#if HAS_CONTRAST
uniform float u_contrast;
#endif
#if HAS_VIGNETTE
uniform vec2 u_vignette;
uniform vec4 u_tan;
uniform vec2 u_size;
uniform vec2 u_centre_tan;
#endif
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) + ivec2(u_margin);
#if HAS_BLUR
  // Vertical half of the separable Gaussian (the horizontal half ran in the pass before).
  vec2 texel = 1.0 / vec2(textureSize(u_src, 0));
  vec2 q0 = (gl_FragCoord.xy + vec2(float(u_margin))) * texel;
  vec3 c = u_centre_weight * texture(u_src, q0).rgb;
  for (int k = 0; k < u_tap_count; ++k) {
    vec2 t = texelFetch(u_taps, ivec2(k, 0), 0).xy;
    vec2 d = vec2(0.0, t.x * texel.y);
    c += t.y * (texture(u_src, q0 + d).rgb + texture(u_src, q0 - d).rgb);
  }
#else
  vec3 c = texelFetch(u_src, p, 0).rgb;
#endif
#if HAS_TINT
  c *= u_tint;
#endif
#if HAS_EXPOSURE
  c *= u_exposure_gain;
#endif
#if HAS_SATURATION
  float y = dot(c, vec3(0.25, 0.5, 0.25));
  c = vec3(y) + u_saturation * (c - vec3(y));
#endif
#if HAS_CONTRAST
  c = vec3(0.5) + u_contrast * (c - vec3(0.5));
#endif
#if HAS_VIGNETTE
  // d: angle between this pixel's ray and the eye's optical axis (atan2 form, accurate near 0).
  vec2 q = gl_FragCoord.xy / u_size;
  vec3 ray = vec3(mix(u_tan.x, u_tan.y, q.x), mix(u_tan.z, u_tan.w, q.y), -1.0);
  vec3 axis = vec3(u_centre_tan, -1.0);
  float d = atan(length(cross(ray, axis)), dot(ray, axis));
  float f = clamp(1.0 - (d - u_vignette.x) / u_vignette.y, 0.0, 1.0);
  c *= f;
#endif
  frag = vec4(c, 1.0);
}
)";
  return s;
}

}  // namespace vdfx::effects
