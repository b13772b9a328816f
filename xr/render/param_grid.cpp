/// @file
/// @brief Baking the parameter grid of per-pixel mode.
#include "xr/render/param_grid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vdfx::xr {

double ParamGrid::max_blur_sigma_deg() const {
  double m = 0.0;
  for (const effects::StackParams& p : cells) m = std::max(m, p.blur_sigma_deg);
  return m;
}

ParamGrid bake_param_grid(const std::function<effects::StackParams(const effects::Direction&)>& at,
                          int width, int height) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("bake_param_grid: empty grid " + std::to_string(width) + "x" +
                                std::to_string(height));
  ParamGrid g{width, height, {}};
  g.cells.reserve(static_cast<std::size_t>(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      g.cells.push_back(at(effects::from_equirect_uv({(i + 0.5) / width, (j + 0.5) / height})));
  return g;
}

}  // namespace vdfx::xr
