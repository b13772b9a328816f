/// @file
/// @brief Golden-image comparison of 8-bit BGR renders (the style of tests/ui/golden.h): max and
/// mean tolerances on 8-bit values; on failure the actual image and an x8 difference are written
/// to the build tree; VDFX_BLESS=1 rewrites the golden instead.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "tests/support/test_paths.h"

namespace vdfx::test_images {

/// Compares `actual` (CV_8UC3 BGR) with tests/MODULE/golden/NAME.png; empty when it matches,
/// else what differs and where the actual and difference images went.
inline std::string compare_with_golden(const cv::Mat& actual, const std::string& module,
                                       const std::string& name, double max_tol, double mean_tol) {
  namespace fs = std::filesystem;
  const std::string golden =
      std::string(VDFX_SOURCE_DIR) + "/tests/" + module + "/golden/" + name + ".png";
  const fs::path out_dir = fs::path(VDFX_TEST_OUTPUT_DIR) / module / "golden";
  fs::create_directories(out_dir);
  const std::string actual_path = (out_dir / (name + ".actual.png")).string();
  const char* bless = std::getenv("VDFX_BLESS");
  if (bless && std::string(bless) == "1") {
    fs::create_directories(fs::path(golden).parent_path());
    cv::imwrite(golden, actual);
    return {};
  }
  const cv::Mat g = cv::imread(golden, cv::IMREAD_COLOR);
  if (g.empty() || g.size() != actual.size()) {
    cv::imwrite(actual_path, actual);
    return "no golden of the right size at " + golden + " (actual " + actual_path +
           "; VDFX_BLESS=1 writes it)";
  }
  cv::Mat diff;
  cv::absdiff(g, actual, diff);
  double max_diff = 0.0;
  cv::minMaxLoc(diff.reshape(1), nullptr, &max_diff);
  const cv::Scalar m = cv::mean(diff);
  const double mean_diff = (m[0] + m[1] + m[2]) / 3.0;
  if (max_diff <= max_tol && mean_diff <= mean_tol) return {};
  cv::imwrite(actual_path, actual);
  cv::Mat amplified;
  diff.convertTo(amplified, CV_8UC3, 8.0);
  const std::string diff_path = (out_dir / (name + ".diff.png")).string();
  cv::imwrite(diff_path, amplified);
  std::ostringstream s;
  s << golden << ": max difference " << max_diff << " (tolerance " << max_tol << "), mean "
    << mean_diff << " (tolerance " << mean_tol << "); actual " << actual_path << ", diff x8 "
    << diff_path << "; VDFX_BLESS=1 rewrites the golden if the change is meant";
  return s.str();
}

}  // namespace vdfx::test_images
