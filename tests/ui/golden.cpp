/// @file
/// @brief Golden-image comparison of golden.h.
#include "golden.h"

#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "tests/support/test_paths.h"
#include "ui/canvas.h"

namespace vdfx::ui::test {

namespace {

cv::Mat premultiply(const cv::Mat& straight) {
  cv::Mat out = straight.clone();
  out.forEach<cv::Vec4b>([](cv::Vec4b& p, const int*) {
    for (int k = 0; k < 3; ++k) p[k] = static_cast<uchar>((p[k] * p[3] + 127) / 255);
  });
  return out;
}

void write_rgba_png(const std::string& path, const cv::Mat& straight_rgba) {
  cv::Mat bgra;
  cv::cvtColor(straight_rgba, bgra, cv::COLOR_RGBA2BGRA);
  cv::imwrite(path, bgra);
}
}  // namespace

std::string golden_dir() {
  return std::string(VDFX_SOURCE_DIR) + "/tests/ui/golden";
}
std::string output_dir() {
  const std::string d = std::string(VDFX_TEST_OUTPUT_DIR) + "/ui";
  std::filesystem::create_directories(d);
  return d;
}

cv::Mat preview_over_grey(const cv::Mat& pm) {
  cv::Mat out(pm.size(), CV_8UC3);
  for (int y = 0; y < pm.rows; ++y)
    for (int x = 0; x < pm.cols; ++x) {
      const cv::Vec4b p = pm.at<cv::Vec4b>(y, x);
      const int back = ((x / 32 + y / 32) % 2) ? 110 : 140;  // checker shows translucency
      const int keep = 255 - p[3];
      for (int k = 0; k < 3; ++k)
        out.at<cv::Vec3b>(y, x)[2 - k] = static_cast<uchar>(p[k] + (back * keep + 127) / 255);
    }
  return out;
}

std::string compare_with_golden(const cv::Mat& actual, const std::string& name,
                                double max_tolerance, double mean_tolerance) {
  const std::string golden = golden_dir() + "/" + name + ".png";
  const char* bless = std::getenv("VDFX_BLESS");
  cv::imwrite(output_dir() + "/" + name + ".preview.png", preview_over_grey(actual));
  if (bless && std::string(bless) == "1") {
    write_rgba_png(golden, unpremultiply(actual));
    return {};
  }
  cv::Mat g = cv::imread(golden, cv::IMREAD_UNCHANGED);
  const std::string actual_path = output_dir() + "/" + name + ".actual.png";
  if (g.empty() || g.type() != CV_8UC4) {
    write_rgba_png(actual_path, unpremultiply(actual));
    return "no RGBA golden at " + golden + " (actual written to " + actual_path +
           "; run with VDFX_BLESS=1 to create it)";
  }
  cv::cvtColor(g, g, cv::COLOR_BGRA2RGBA);
  if (g.size() != actual.size()) {
    write_rgba_png(actual_path, unpremultiply(actual));
    std::ostringstream s;
    s << golden << ": size " << g.cols << "x" << g.rows << " but actual is " << actual.cols << "x"
      << actual.rows << " (actual written to " << actual_path << ")";
    return s.str();
  }
  cv::Mat diff;
  cv::absdiff(premultiply(g), actual, diff);
  double max_diff = 0.0;
  cv::minMaxLoc(diff.reshape(1), nullptr, &max_diff);
  const cv::Scalar m = cv::mean(diff);
  const double mean_diff = (m[0] + m[1] + m[2] + m[3]) / 4.0;
  if (max_diff <= max_tolerance && mean_diff <= mean_tolerance) return {};
  write_rgba_png(actual_path, unpremultiply(actual));
  cv::Mat amplified, diff_rgb;
  diff.convertTo(amplified, CV_8UC4, 8.0);
  cv::cvtColor(amplified, diff_rgb, cv::COLOR_RGBA2BGR);
  const std::string diff_path = output_dir() + "/" + name + ".diff.png";
  cv::imwrite(diff_path, diff_rgb);
  std::ostringstream s;
  s << golden << ": max difference " << max_diff << " (tolerance " << max_tolerance << "), mean "
    << mean_diff << " (tolerance " << mean_tolerance << "); actual " << actual_path << ", diff x8 "
    << diff_path << "; VDFX_BLESS=1 rewrites the golden if the change is meant";
  return s.str();
}

}  // namespace vdfx::ui::test
