/// @file
/// @brief GLSL sources of the effect stack (strings only: effects/ never links GL).
///
/// The stack runs in at most two full-screen passes over a float eye buffer:
///  1. horizontal Gaussian (only when blur is active),
///  2. vertical Gaussian (when blur is active) fused with the per-pixel effects in the paper's
///     order: tint, exposure, saturation, contrast, vignette.
/// Only the active effects are compiled in: the source of pass 2 is generated from a bit mask
/// (bit i = EffectType i) and the GL side caches one program per mask.
#pragma once

#include <string>

#include "effects/effect_types.h"

namespace vdfx::effects {

/// Bit of one effect in a shader mask.
constexpr unsigned shader_bit(EffectType t) { return 1u << static_cast<unsigned>(t); }
inline constexpr unsigned kAllEffectsMask = (1u << kEffectCount) - 1u;

/// The effects of `p` that change some pixel (StackParams::is_neutral is false).
unsigned non_neutral_mask(const StackParams& p);

/// Pass 1: horizontal Gaussian. Uniforms: u_src (linear filtering, clamp to edge), u_taps (an
/// RG32F row: texel k = (offset, weight) of the symmetric pair of taps k), u_tap_count,
/// u_centre_weight. Two neighbouring kernel taps i, i+1 are read with one bilinear fetch at
/// i + w_{i+1} / (w_i + w_{i+1}) weighted w_i + w_{i+1} (exact for linear filtering), halving the
/// fetches; clamp-to-edge makes taps beyond the border read the border pixel (replicate).
std::string blur_horizontal_fragment_source();

/// Pass 2 for the effects in `mask`. Uniforms (present only when their effect is compiled in):
/// u_src, u_margin (the source has this many extra pixels on every side: the target reads the
/// source's interior, so a blur sees real image beyond the view's border); blur: u_taps, u_tap_count, u_centre_weight (as pass 1, vertical); u_tint (vec3 gain), u_exposure_gain (2^stops),
/// u_saturation, u_contrast, u_vignette (radius, falloff in radians); vignette geometry u_tan
/// (left, right, down, up tangents), u_size (pixels), u_centre_tan (optical centre).
std::string stack_fragment_source(unsigned mask);

}  // namespace vdfx::effects
