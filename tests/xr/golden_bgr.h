/// @file
/// @brief Golden screenshots of the xr tests (BGR 8-bit, tests/xr/golden/NAME.png): max and mean
/// tolerances, the actual image and an x8 difference written to the build tree on failure;
/// VDFX_BLESS=1 rewrites the golden. Look at a golden before committing it.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

namespace vdfx::xr::test {

/// Empty when `actual` matches the golden within the tolerances (8-bit levels), else what failed.
inline std::string compare_with_golden(const cv::Mat& actual, const std::string& name,
                                       double max_tol, double mean_tol) {
  namespace fs = std::filesystem;
  const std::string golden = std::string(VDFX_SOURCE_DIR) + "/tests/xr/golden/" + name + ".png";
  const fs::path out_dir = fs::path(VDFX_TEST_OUTPUT_DIR) / "xr" / "golden";
  fs::create_directories(out_dir);
  const std::string actual_path = (out_dir / (name + ".png")).string();
  cv::imwrite(actual_path, actual);
  if (const char* bless = std::getenv("VDFX_BLESS"); bless && std::string(bless) == "1") {
    fs::create_directories(fs::path(golden).parent_path());
    cv::imwrite(golden, actual);
  }
  const cv::Mat g = cv::imread(golden, cv::IMREAD_COLOR);
  if (g.empty() || g.size() != actual.size())
    return "no golden of the right size at " + golden + " (actual " + actual_path +
           "; VDFX_BLESS=1 writes it)";
  cv::Mat d;
  cv::absdiff(g, actual, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  const double mean = cv::mean(d.reshape(1))[0];
  if (mx <= max_tol && mean <= mean_tol) return {};
  cv::imwrite((out_dir / (name + "_diff_x8.png")).string(), d * 8);
  return golden + ": max difference " + std::to_string(mx) + " (tolerance " +
         std::to_string(max_tol) + "), mean " + std::to_string(mean) + " (tolerance " +
         std::to_string(mean_tol) + "); actual " + actual_path;
}

}  // namespace vdfx::xr::test
