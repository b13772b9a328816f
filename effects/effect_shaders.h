/// @file
/// @brief GLSL sources of the effect stack (strings only: effects/ never links GL).
///
/// The stack ends in one full-screen pass over a float eye buffer that applies the per-pixel
/// effects in the paper's order (tint, exposure, saturation, contrast, vignette) to the blurred
/// colour. Where that colour comes from (StackShader::blur):
///  - FusedVertical (exact separable blur): pass 1 is a horizontal Gaussian (blur_1d), the stack
///    pass does the vertical half itself;
///  - Blurred: the blur ran before (pyramid) into a smaller image read bilinearly;
///  - Levels (per-pixel blur): a stack of images blurred with sigmas tau_j = tau_1 r^(j-1), each
///    pixel mixes the two levels around its own sigma with the weight that matches its variance
///    (below tau_1 the unblurred source and level 1).
/// With per_pixel the parameters come from the baked grid (float textures) looked up along each
/// pixel's own view ray, bilinear, wrapping in azimuth; otherwise from uniforms (view mode).
/// Only the active effects are compiled in: the source is generated from a bit mask
/// (bit i = EffectType i) and the GL side caches one program per variant.
#pragma once

#include <string>

#include "effects/effect_types.h"

namespace vdfx::effects {

/// Bit of one effect in a shader mask.
constexpr unsigned shader_bit(EffectType t) {
  return 1u << static_cast<unsigned>(t);
}
inline constexpr unsigned kAllEffectsMask = (1u << kEffectCount) - 1u;

/// The effects of `p` that change some pixel (StackParams::is_neutral is false).
unsigned non_neutral_mask(const StackParams& p);

/// Most blur levels a Levels variant reads (texture units: source, three grid textures, levels).
inline constexpr int kMaxBlurLevels = 12;

/// One variant of the stack pass.
struct StackShader {
  enum class Blur { None, FusedVertical, Blurred, Levels };
  unsigned mask = 0;  //!< effects compiled in (blur's bit is implied by `blur`)
  Blur blur = Blur::None;
  bool per_pixel = false;  //!< parameters from the grid textures instead of uniforms
  int levels = 0;          //!< Levels: number of blurred levels (1..kMaxBlurLevels)
  bool operator<(const StackShader& o) const;
};

/// 1-D Gaussian along u_dir (texels: (1, 0) horizontal, (0, 1) vertical), target and source the
/// same size. Uniforms: u_src (linear filtering, clamp to edge), u_dir, u_taps (an RG32F row:
/// texel k = (offset, weight) of the symmetric pair of taps k), u_tap_count, u_centre_weight.
/// Two neighbouring kernel taps i, i+1 are read with one bilinear fetch at
/// i + w_{i+1} / (w_i + w_{i+1}) weighted w_i + w_{i+1} (exact for linear filtering), halving the
/// fetches; clamp-to-edge makes taps beyond the border read the border pixel (replicate).
std::string blur_1d_fragment_source();

/// Halves an image with the binomial kernel [1 3 3 1] / 8 per axis (variance 3/4 source pixel^2):
/// target texel j is centred on source coordinate 2 j + 1, and the kernel is four bilinear
/// fetches at +-0.75 source pixels. Uniform: u_src (linear filtering, clamp to edge).
std::string downsample_fragment_source();

/// The stack pass. Uniforms (present only when their part is compiled in): u_src, u_margin (the
/// source has this many extra pixels on every side: the target reads the source's interior, so a
/// blur sees real image beyond the view's border); FusedVertical: u_taps, u_tap_count,
/// u_centre_weight (as blur_1d, vertical); Blurred: u_blurred, u_blurred_scale (source pixels per
/// texel of u_blurred); Levels: u_level1..u_levelN, u_level_scale[N], u_tau1_deg,
/// u_level_log2r (log2 of the level ratio r); view mode: u_tint (vec3 gain), u_exposure_gain
/// (2^stops), u_saturation, u_contrast, u_vignette (radius, falloff in radians); per_pixel: u_grid0
/// (tint r, g, b, stops), u_grid1 (saturation, contrast, vignette radius and falloff in radians),
/// u_grid2 (blur sigma in degrees), u_rot (eye -> world); geometry: u_tan (left, right, down, up
/// tangents), u_size (pixels), u_centre_tan (optical centre).
std::string stack_fragment_source(const StackShader& variant);
/// View-mode variant of `mask` with the exact (fused) blur.
std::string stack_fragment_source(unsigned mask);

}  // namespace vdfx::effects
