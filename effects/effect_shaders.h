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

/// Pass 1: horizontal Gaussian. Uniforms: u_src, u_radius (int), u_inv_two_sigma2, u_norm
/// (1 / sum of the weights, computed in double on the CPU). Replicates the border pixel.
std::string blur_horizontal_fragment_source();

/// Pass 2 for the effects in `mask`. Uniforms (present only when their effect is compiled in):
/// u_src; blur: u_radius, u_inv_two_sigma2, u_norm; u_tint (vec3 gain), u_exposure_gain (2^stops),
/// u_saturation, u_contrast, u_vignette (radius, falloff in radians); vignette geometry u_tan
/// (left, right, down, up tangents), u_size (pixels), u_centre_tan (optical centre).
std::string stack_fragment_source(unsigned mask);

}  // namespace vdfx::effects
