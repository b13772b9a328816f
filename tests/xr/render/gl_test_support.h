/// @file
/// @brief Shared pieces of the GL tests: one hidden context per test binary, test images.
///
/// GL tests never skip: without a display the fixture fails each test with the context's error
/// ("run under xvfb-run -a").
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "xr/render/gl_context.h"

namespace vdfx::xr::test {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (context() || !error().empty()) return;
    try {
      context() = GlContext::create();
    } catch (const GlError& e) {
      error() = e.what();
    }
  }
  void SetUp() override {
    ASSERT_TRUE(context()) << "GL test cannot run: " << error();
    context()->make_current();
  }
  static std::unique_ptr<GlContext>& context() {
    static std::unique_ptr<GlContext> c;
    return c;
  }
  static std::string& error() {
    static std::string e;
    return e;
  }
};

/// A real 1024x512 equirect (Blender's CC0 "sunrise" studio light, HDR), tone-mapped simply
/// (x / (1 + x), then gamma 1/2.2) to BGR float in [0, 1].
inline cv::Mat sunrise_float() {
  setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1);
  const std::string path = "/usr/share/blender/datafiles/studiolights/world/sunrise.exr";
  cv::Mat hdr = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (hdr.empty()) throw std::runtime_error("cannot read " + path + " (package blender-data)");
  if (hdr.channels() == 4) cv::cvtColor(hdr, hdr, cv::COLOR_BGRA2BGR);
  hdr.convertTo(hdr, CV_32FC3);
  cv::Mat out(hdr.size(), CV_32FC3);
  hdr.forEach<cv::Vec3f>([&](const cv::Vec3f& c, const int* pos) {
    cv::Vec3f o;
    for (int k = 0; k < 3; ++k) {
      const float x = std::max(c[k], 0.0f);
      o[k] = std::pow(x / (1.0f + x), 1.0f / 2.2f);
    }
    out.at<cv::Vec3f>(pos[0], pos[1]) = o;
  });
  return out;
}

/// Max and mean absolute difference over all channels of two same-size float images.
struct ErrorStats {
  double max = 0.0, mean = 0.0;
};
inline ErrorStats compare(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask = {}) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  d = d.reshape(1, d.rows);
  ErrorStats s;
  double n = 0.0;
  const int ch = a.channels();
  for (int y = 0; y < d.rows; ++y)
    for (int x = 0; x < d.cols; ++x) {
      if (!mask.empty() && !mask.at<uchar>(y, x / ch)) continue;
      const double v = d.at<float>(y, x);
      s.max = std::max(s.max, v);
      s.mean += v;
      n += 1.0;
    }
  s.mean /= std::max(n, 1.0);
  return s;
}

/// BGR float (first three channels of a BGRA readback), clamped to [0, 1].
inline cv::Mat bgr_clamped(const cv::Mat& bgra) {
  cv::Mat bgr;
  if (bgra.channels() == 4)
    cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  else
    bgr = bgra.clone();
  cv::min(cv::max(bgr, 0.0), 1.0, bgr);
  return bgr;
}

}  // namespace vdfx::xr::test
