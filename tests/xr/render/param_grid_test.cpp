/// @file
/// @brief Per-pixel mode's parameter grid: cell centres and the largest sigma.
#include "xr/render/param_grid.h"

#include <gtest/gtest.h>

namespace vdfx::xr {
namespace {

TEST(ParamGrid, CellsSampleTheirCentres) {
  const ParamGrid g = bake_param_grid(
      [](const effects::Direction& d) {
        effects::StackParams p;
        p.exposure_stops = d.azimuth_deg / 100.0;
        p.contrast = 1.0 + d.altitude_deg / 100.0;
        p.blur_sigma_deg = d.altitude_deg > 0 ? d.altitude_deg / 10.0 : 0.0;
        return p;
      },
      8, 4);
  ASSERT_EQ(g.cells.size(), 32u);
  // Column i centre: azimuth (i + 0.5) / 8 * 360 - 180; row j centre: altitude 90 - (j + 0.5) 45.
  EXPECT_NEAR(g.at(0, 0).exposure_stops, -1.575, 1e-12);
  EXPECT_NEAR(g.at(7, 0).exposure_stops, 1.575, 1e-12);
  EXPECT_NEAR(g.at(0, 0).contrast, 1.675, 1e-12);
  EXPECT_NEAR(g.at(0, 3).contrast, 0.325, 1e-12);
  EXPECT_NEAR(g.max_blur_sigma_deg(), 6.75, 1e-12);  // the top row, altitude 67.5
  EXPECT_THROW(
      bake_param_grid([](const effects::Direction&) { return effects::StackParams{}; }, 0, 4),
      std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::xr
