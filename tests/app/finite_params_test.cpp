/// @file
/// @brief Issue 11, class 4, the renderer's backstop: parameters that are not finite are refused
/// with the sidecar and the view named (they rendered a black image, and eval printed null).
#include "app/cli/finite_params.h"

#include <gtest/gtest.h>

#include <limits>

#include "io/input_error.h"

namespace vdfx::app {
namespace {

TEST(ViewRenderFinite, NonFiniteParametersAreRefusedNamingTheSidecarAndView) {
  const effects::StackParams ok;
  EXPECT_NO_THROW(require_finite(ok, "s.vdfx.json", {10.0, 5.0}, 3));
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    effects::StackParams p;
    p.exposure_stops = bad;
    try {
      require_finite(p, "s.vdfx.json", {10.0, 5.0}, 3);
      FAIL() << "accepted " << bad;
    } catch (const io::InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find("s.vdfx.json: "), 0u) << msg;
      EXPECT_NE(msg.find("not finite at 10,5,3"), std::string::npos) << msg;
    }
  }
  effects::StackParams tint;
  tint.tint_gain.z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(require_finite(tint, "s", {0.0, 0.0}, 0), io::InputError);
}

}  // namespace
}  // namespace vdfx::app
