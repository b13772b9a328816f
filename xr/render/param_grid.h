/// @file
/// @brief Per-pixel mode's parameter grid: the whole stack's parameters baked at the cell centres
/// of a coarse equirect grid (the speed/error knob, `--bake WxH`, default 256 x 128). GL-free; the
/// effect stack uploads it as float textures (EffectStackGl::set_param_grid) and every eye pixel
/// reads its parameters bilinearly along its own view ray, wrapping in azimuth.
#pragma once

#include <functional>
#include <vector>

#include "effects/coords.h"
#include "effects/effect_types.h"

namespace vdfx::xr {

struct ParamGrid {
  int width = 0, height = 0;
  std::vector<effects::StackParams> cells;  //!< row-major, row 0 at the top (altitude +90)
  const effects::StackParams& at(int i, int j) const {
    return cells[static_cast<std::size_t>(j) * width + i];
  }
  /// The largest blur sigma of any cell (degrees): the eye's blur margin and the level stack's
  /// range in per-pixel mode.
  double max_blur_sigma_deg() const;
};

/// Parameters at the centre of every cell: u = (i + 0.5) / width, v = (j + 0.5) / height.
/// Throws std::invalid_argument on an empty grid.
ParamGrid bake_param_grid(const std::function<effects::StackParams(const effects::Direction&)>& at,
                          int width, int height);

}  // namespace vdfx::xr
