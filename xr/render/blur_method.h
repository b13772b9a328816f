/// @file
/// @brief The GPU blur's speed/error knob (GL-free, so command lines can name it without GL).
#pragma once

#include <optional>
#include <string_view>

namespace vdfx::xr {

/// Exact: separable Gaussian at full resolution (the contract's kernel; `vdfx render --gpu`).
/// Pyramid: binomial halvings, a small residual blur, bilinear upsampling (blur_pyramid_gl.h);
/// the live default of `vdfx play` / `vdfx edit`.
enum class BlurMethod { Exact, Pyramid };
std::string_view blur_method_name(BlurMethod m);  //!< "exact", "pyramid"
std::optional<BlurMethod> blur_method_from_name(std::string_view name);

/// Per-pixel mode's blur levels: the ratio between successive level sigmas. A pixel mixes the two
/// levels around its own sigma; the closer they are, the closer the mixture is to one Gaussian
/// (and the more levels are blurred). Measured in docs/compositor.md.
inline constexpr double kOctaveLevels = 2.0;
inline constexpr double kHalfOctaveLevels = 1.4142135623730951;  // sqrt(2)

}  // namespace vdfx::xr
