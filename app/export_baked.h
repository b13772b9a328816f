/// @file
/// @brief The baked export's frame: every equirect pixel gets the effects' parameters
/// interpolated at its own direction and frame (the paper's per-pixel mode over the whole
/// sphere), the blur is an angular blur on the sphere (effects/equirect_blur.h), and the colour
/// effects apply per pixel with the CPU reference formulas (effects/effect_stack.h).
///
/// View-dependent by nature, and therefore left out: the vignette (its falloff is measured from
/// the eye's optical centre, which a baked sphere does not have) and flare and grain.
///
/// Parameters: evaluated exactly (StackInterpolator) at the pixels of a grid every `param_step`
/// pixels in both directions (wrapping across the azimuth seam, always including the bottom
/// row), bilinear in between; tint gains renormalised after the blend as after any
/// interpolation. param_step 1 evaluates every pixel. docs/export.md gives the measured
/// difference between the default step and 1.
#pragma once

#include <cstdint>

#include <opencv2/core.hpp>

#include "effects/stack_interpolator.h"

namespace vdfx::app {

struct BakedOptions {
  int param_step = 0;  //!< 0: automatic (the grid at most 1024 columns: 1 up to 1024-wide video)
};

/// The step `options` resolves to for a video `width` pixels wide.
int baked_param_step(const BakedOptions& options, int width);

/// True when the stack has an effect a baked export leaves out (the vignette).
bool baked_drops_effects(const effects::StackInterpolator& stack);

/// Renders frame `frame` of an equirect (CV_32FC3 RGB, display-encoded): unclamped CV_32FC3.
cv::Mat render_baked(const cv::Mat& equirect, const effects::StackInterpolator& stack,
                     std::int64_t frame, const BakedOptions& options = {});

}  // namespace vdfx::app
