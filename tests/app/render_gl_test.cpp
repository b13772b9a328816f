/// @file
/// @brief `vdfx render --gpu` against the CPU reference path of the same command (needs a
/// display: CI runs it under Xvfb; without one it fails, never skips).
#include <gtest/gtest.h>

#include "command_test_util.h"

namespace vdfx::app::testing {
namespace {

double max_abs_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  return mx;
}

TEST(RenderGpu, MatchesCpuReferenceForTheWholeStack) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  // Every colour effect plus a vignette: exposure from the base sidecar, the rest constant.
  write_text(dir / "s.vdfx.json",
             exposure_sidecar(R"(,
    {"type": "tint", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
      "params": {"gain": [1.2, 1.0, 0.8]}}]},
    {"type": "saturation", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
      "params": {"amount": 0.6}}]},
    {"type": "contrast", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
      "params": {"amount": 1.3}}]},
    {"type": "vignette", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
      "params": {"radius_deg": 20.0, "falloff_deg": 30.0}}]})"));
  const std::string common = "--view 30,10,5 --frame 0 --fov 90 --size 160x120 ";
  const cv::Mat cpu = render(dir, common, "cpu.png");
  const cv::Mat gpu = render(dir, common + "--gpu", "gpu.png");
  ASSERT_EQ(cpu.size(), gpu.size());
  const double err = max_abs_diff(cpu, gpu);
  std::cout << "render --gpu vs CPU: max abs error " << err << "/255\n";
  EXPECT_LE(err, 2.0);
  EXPECT_GT(cv::mean(cpu)[1], 5.0);  // not a black frame on both sides
}

TEST(RenderGpu, HmdEyeWithPredistortionMatchesCpu) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const std::string common = "--view 0,0 --hmd generic90 --eye right --size 144x160 ";
  for (const char* distort : {"none", "pixel", "mesh:65"}) {
    const std::string args = common + "--distort " + distort;
    const cv::Mat cpu = render(dir, args, "cpu.png");
    const cv::Mat gpu = render(dir, args + " --gpu", "gpu.png");
    ASSERT_EQ(cpu.size(), gpu.size());
    cv::Mat d;
    cv::absdiff(cpu, gpu, d);
    const double mean = cv::mean(d.reshape(1))[0];
    std::cout << "--distort " << distort << ": mean abs diff GPU vs CPU " << mean << "/255\n";
    // Edges of the grid lines differ by a pixel's interpolation at most; on average the two
    // paths agree closely.
    EXPECT_LT(mean, 2.0) << distort;
  }
}

}  // namespace
}  // namespace vdfx::app::testing
