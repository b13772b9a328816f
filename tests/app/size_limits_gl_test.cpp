/// @file
/// @brief Issue 11, class 3 on the GPU path: the area the GPU renders (the blur's margin
/// included) is checked against the GL implementation and kGpuRenderLimit before any texture is
/// allocated (it was GL_OUT_OF_MEMORY, exit 3, after 6 GB).
#include <gtest/gtest.h>

#include "app/cli/size_limits.h"
#include "command_test_util.h"

namespace vdfx::app::testing {
namespace {

TEST(SizeLimitsGl, TheBlurMarginCountsTowardsTheGpuLimit) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json",
             exposure_sidecar(R"(, {"type": "blur", "keyframes": [{"azimuth_deg": 0.0,
                "altitude_deg": 0.0, "frame": 0, "params": {"sigma_deg": 10.0}}]})"));
  const std::string common = "render " + (dir / "pano.png").string() + " --sidecar " +
                             (dir / "s.vdfx.json").string() + " --view 0,0 --fov 90 --gpu ";
  // 8192x4096 is within the limit by itself; its blur margin takes it beyond.
  const CommandResult big = run_vdfx(common + "--size 8192x4096 --out " + (dir / "o.png").string());
  EXPECT_EQ(big.exit_code, 2) << big.output;
  EXPECT_NE(big.output.find("with the blur's margin of"), std::string::npos) << big.output;
  EXPECT_NE(big.output.find(std::to_string(kGpuRenderLimit.max_pixels)), std::string::npos)
      << big.output;
  // A size whose margin fits renders.
  const CommandResult ok = run_vdfx(common + "--size 256x128 --out " + (dir / "ok.png").string());
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

}  // namespace
}  // namespace vdfx::app::testing
