/// @file
/// @brief `vdfx render --gpu` on stereo and VR180 frames: the GL video layer's per-eye images
/// (xr::VideoLayerGl::set_layout) against the CPU reference of the same eye within 2/255, and no
/// blur (exact or pyramid) reading the other eye. docs/stereo.md.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "command_test_util.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx;
using testing::test_dir;
using testing::write_text;

/// Eye `e`'s smooth pattern, w x h, BGR 8-bit.
cv::Mat pattern(int e, int w, int h) {
  cv::Mat m(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double a = std::sin(6.283185307 * (x + 0.5) / w),
                   b = std::cos(3.14159265 * (y + 0.5) / h);
      m.at<cv::Vec3b>(y, x) = e == 0 ? cv::Vec3b(cv::saturate_cast<uchar>(90 + 50 * b), 40,
                                                 cv::saturate_cast<uchar>(170 + 60 * a))
                                     : cv::Vec3b(cv::saturate_cast<uchar>(160 + 60 * a),
                                                 cv::saturate_cast<uchar>(150 + 70 * b), 40);
    }
  return m;
}

std::string sidecar(int w, int h, const std::string& effects) {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "f.png", "fps": 24.0, "frames": 1, "width": )" +
         std::to_string(w) + R"(, "height": )" + std::to_string(h) + R"(},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": [)" +
         effects + "]}";
}

cv::Mat render(const fs::path& dir, const fs::path& png, const std::string& args) {
  static int n = 0;
  const fs::path out = dir / ("r" + std::to_string(n++) + ".png");
  const testing::CommandResult r =
      run_vdfx("render " + png.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --fov 70 --size 80x60 " + args + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  cv::Mat img = cv::imread(out.string(), cv::IMREAD_COLOR);
  return img.empty() ? cv::Mat(60, 80, CV_8UC3, cv::Scalar::all(0)) : img;
}

const char* kTint =
    R"({"type": "exposure", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
    "params": {"stops": 0.5}}]})";

TEST(StereoRenderGpu, EachEyeMatchesTheCpuReference) {
  const fs::path dir = test_dir();
  const struct {
    const char* layout;
    int coverage;
  } rows[] = {{"top-bottom", 360}, {"left-right", 360}, {"right-left", 360}, {"left-right", 180}};
  for (const auto& row : rows) {
    const int eye_w = row.coverage == 360 ? 256 : 128;
    const cv::Mat l = pattern(0, eye_w, 128), r = pattern(1, eye_w, 128);
    cv::Mat frame;
    if (std::string(row.layout) == "top-bottom") cv::vconcat(l, r, frame);
    if (std::string(row.layout) == "left-right") cv::hconcat(l, r, frame);
    if (std::string(row.layout) == "right-left") cv::hconcat(r, l, frame);
    const fs::path png = dir / "f.png";
    cv::imwrite(png.string(), frame);
    write_text(dir / "s.vdfx.json", sidecar(frame.cols, frame.rows, kTint));
    const std::string base =
        std::string("--layout ") + row.layout + " --coverage " + std::to_string(row.coverage);
    for (const std::string view : {"0,0", "60,10", "-75,-5", "100,0"}) {
      for (const std::string eye : {"left", "right"}) {
        SCOPED_TRACE(std::string(row.layout) + " " + std::to_string(row.coverage) + " " + view +
                     " " + eye);
        const std::string args = base + " --view " + view + " --eye " + eye;
        const cv::Mat cpu = render(dir, png, args);
        const cv::Mat gpu = render(dir, png, args + " --gpu");
        EXPECT_LE(testing::max_abs_diff(cpu, gpu), 2.0);
        const cv::Mat other = render(
            dir, png, base + " --view " + view + " --eye " + (eye == "left" ? "right" : "left"));
        EXPECT_GT(testing::max_abs_diff(cpu, other), 40.0);
      }
    }
  }
}

TEST(StereoRenderGpu, NoBlurReadsTheOtherEye) {
  const fs::path dir = test_dir();
  const cv::Mat red(128, 256, CV_8UC3, cv::Scalar(0, 0, 255)),
      blue(128, 256, CV_8UC3, cv::Scalar(255, 0, 0));
  const std::string blur =
      R"({"type": "blur", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
      "params": {"sigma_deg": 4.0}}]})";
  for (const std::string layout : {"top-bottom", "left-right"}) {
    cv::Mat frame;
    if (layout == "top-bottom")
      cv::vconcat(red, blue, frame);
    else
      cv::hconcat(red, blue, frame);
    const fs::path png = dir / "f.png";
    cv::imwrite(png.string(), frame);
    write_text(dir / "s.vdfx.json", sidecar(frame.cols, frame.rows, blur));
    for (const std::string view : {"180,0", "0,-85", "0,85"}) {
      for (const std::string method : {"exact", "pyramid"}) {
        SCOPED_TRACE(layout + " " + view + " " + method);
        const std::string args =
            "--gpu --layout " + layout + " --view " + view + " --blur " + method;
        std::vector<cv::Mat> lc, rc;
        cv::split(render(dir, png, args + " --eye left"), lc);
        cv::split(render(dir, png, args + " --eye right"), rc);
        EXPECT_EQ(cv::countNonZero(lc[0]), 0);  // BGR: no blue in the left (red) eye
        EXPECT_EQ(cv::countNonZero(rc[2]), 0);  // no red in the right (blue) eye
      }
    }
  }
}

}  // namespace
}  // namespace vdfx::app
