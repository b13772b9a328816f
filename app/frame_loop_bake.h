/// @file
/// @brief Per-pixel parameter mode on the GPU path: the stack's parameters baked on a coarse
/// equirect grid (a speed/error knob, default 256 x 128) and applied per pixel of the equirect
/// frame before it is uploaded, each pixel reading its parameters bilinearly from the grid.
///
/// Only the colour effects (tint, exposure, saturation, contrast) are baked: they are functions of
/// a pixel's colour and its parameters, so they can be applied on the sphere. Blur and vignette
/// are defined relative to the view (a kernel in degrees of visual angle, an angle from the eye's
/// optical centre) and stay view-dependent in this mode (docs/player.md).
#pragma once

#include <functional>
#include <vector>

#include <opencv2/core.hpp>

#include "effects/coords.h"
#include "effects/effect_types.h"

namespace vdfx::app {

/// The effects that per-pixel mode bakes into the frame.
unsigned baked_effects_mask();

struct ParamGrid {
  int width = 0, height = 0;
  std::vector<effects::StackParams> cells;  //!< row-major, row 0 at the top (altitude +90)
  const effects::StackParams& at(int i, int j) const { return cells[j * width + i]; }
};

/// Parameters at the centre of every cell: u = (i + 0.5) / width, v = (j + 0.5) / height.
ParamGrid bake_param_grid(const std::function<effects::StackParams(const effects::Direction&)>& at,
                          int width, int height);

/// The baked colour effects of `active_mask` applied per pixel of an RGB equirect frame (CV_8UC3
/// or CV_32FC3, values in [0, 1] as encoded); parameters are bilinear in the grid, wrapping in
/// azimuth. Returns CV_32FC3 RGB, unclamped (the compositor clamps at the very end).
cv::Mat apply_param_grid(const cv::Mat& rgb, const ParamGrid& grid, unsigned active_mask);

}  // namespace vdfx::app
