/// @file
/// @brief `vdfx render --gpu` against the CPU reference path of the same command (needs a
/// display: CI runs it under Xvfb; without one it fails, never skips).
#include <gtest/gtest.h>

#include "command_test_util.h"

namespace vdfx::app::testing {
namespace {

TEST(RenderGpu, MatchesCpuReferenceForTheWholeStack) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  // Every colour effect plus a vignette: exposure from the base sidecar, the rest constant.
  write_text(dir / "s.vdfx.json", exposure_sidecar(R"(,
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

// The demo (its sidecar on Blender's interior panorama, 1024x512) at the views where point
// sampling and GL's isotropic mip level used to differ most (26, 75 and 117/255 at 320x240):
// views that shrink the panorama, down to the nadir. Both paths filter each pixel's footprint
// (docs/effects.md, "Sampling a view"), so they agree at every size.
TEST(RenderGpu, ViewsThatShrinkThePanoramaMatchTheCpu) {
  const auto dir = test_dir();
  const std::string input = "/usr/share/blender/datafiles/studiolights/world/interior.exr";
  const std::string sidecar = std::string(VDFX_SOURCE_DIR) + "/app/demo/interior.vdfx.json";
  const struct {
    const char* view;
    int fov;
    const char* size;
  } views[] = {{"31,5", 120, "320x240"},
               {"0,-60", 60, "320x240"},
               {"0,-90", 120, "320x240"},
               {"0,-90", 120, "64x48"}};
  for (const auto& v : views) {
    const std::string args = "render " + input + " --sidecar " + sidecar + " --view " + v.view +
                             " --fov " + std::to_string(v.fov) + " --size " + v.size + " --out ";
    const CommandResult cpu = run_vdfx(args + (dir / "cpu.png").string());
    const CommandResult gpu = run_vdfx(args + (dir / "gpu.png").string() + " --gpu");
    ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
    ASSERT_EQ(gpu.exit_code, 0) << gpu.output;
    const cv::Mat a = cv::imread((dir / "cpu.png").string()),
                  b = cv::imread((dir / "gpu.png").string());
    ASSERT_EQ(a.size(), b.size());
    const double mx = max_abs_diff(a, b), mean = mean_abs_diff(a, b);
    std::cout << "demo --view " << v.view << " --fov " << v.fov << " --size " << v.size
              << ": --gpu vs CPU max " << mx << "/255, mean " << mean << "/255\n";
    EXPECT_LE(mx, 2.0) << v.view << " " << v.size;
  }
}

// Exposure from the base sidecar plus a blur that grows from 0 at azimuth -40 to 4 deg at +40: both
// vary across a 90-degree view at azimuth 0, so view and pixel mode differ visibly.
std::string graded_blur_sidecar() {
  return exposure_sidecar(R"(,
    {"type": "blur", "keyframes": [
      {"azimuth_deg": 40.0, "altitude_deg": 0.0, "frame": 0, "params": {"sigma_deg": 4.0}},
      {"azimuth_deg": -40.0, "altitude_deg": 0.0, "frame": 0, "params": {"sigma_deg": 0.0}}]})");
}

TEST(RenderGpu, PixelModeMatchesCpuPixelMode) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", graded_blur_sidecar());
  const std::string common = "--view 0,0 --frame 0 --fov 90 --size 160x120 ";
  const cv::Mat cpu = render(dir, common + "--mode pixel", "cpu.png");
  const cv::Mat gpu = render(dir, common + "--mode pixel --gpu", "gpu.png");
  const cv::Mat coarse = render(dir, common + "--mode pixel --gpu --bake 16x8", "coarse.png");
  const cv::Mat view = render(dir, common + "--gpu", "view.png");
  ASSERT_EQ(cpu.size(), gpu.size());
  cv::Mat d;
  cv::absdiff(cpu, gpu, d);
  const double err = max_abs_diff(cpu, gpu), mean = cv::mean(d.reshape(1))[0];
  const double coarse_err = max_abs_diff(cpu, coarse), view_err = max_abs_diff(cpu, view);
  std::cout << "render --gpu --mode pixel vs CPU --mode pixel: max " << err << "/255, mean " << mean
            << "/255; --bake 16x8: max " << coarse_err << "/255; GPU view mode: max " << view_err
            << "/255\n";
  // 8-bit outputs of two float pipelines: rounding (1) plus the level mix of the per-pixel blur.
  EXPECT_LE(err, 3.0);
  EXPECT_LT(mean, 0.5);
  EXPECT_GT(view_err, err + 10.0) << "view mode must differ from the per-pixel reference";
  EXPECT_GT(coarse_err, err) << "a 16x8 grid must err more than the default";
}

TEST(RenderGpu, PyramidBlurIsCloseToExact) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", graded_blur_sidecar());
  for (const char* mode : {"view", "pixel"}) {
    // --bake only where it does something (elsewhere it is a usage error).
    const std::string common = std::string("--view 25,0 --fov 60 --size 240x180 --gpu --mode ") +
                               mode + (std::string(mode) == "pixel" ? " --bake 256x128" : "");
    const cv::Mat exact = render(dir, common, "exact.png");
    const cv::Mat pyramid = render(dir, common + " --blur pyramid", "pyramid.png");
    ASSERT_EQ(exact.size(), pyramid.size());
    cv::Mat d;
    cv::absdiff(exact, pyramid, d);
    const double mean = cv::mean(d.reshape(1))[0], mx = max_abs_diff(exact, pyramid);
    std::cout << "--mode " << mode << ": --blur pyramid vs exact: max " << mx << "/255, mean "
              << mean << "/255\n";
    if (std::string(mode) == "view") {  // exact is the default
      EXPECT_EQ(max_abs_diff(exact, render(dir, common + " --blur exact", "named.png")), 0.0);
    }
    // Measured: max 1/255, mean 0.05/255 (an 8-bit rounding step here and there).
    EXPECT_GT(mean, 0.0) << mode << ": the pyramid must actually run";
    EXPECT_LT(mean, 0.5) << mode;
    EXPECT_LE(mx, 4.0) << mode;
  }
}

}  // namespace
}  // namespace vdfx::app::testing
