/// @file
/// @brief Reinhard et al. 2002 global tone mapping followed by sRGB encoding.
#include "io/tone_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::io {

namespace {
double luminance(const cv::Vec3f& c) {
  return kRec709R * c[0] + kRec709G * c[1] + kRec709B * c[2];
}
/// Radiance files can hold negative or non-finite samples; they carry no displayable light.
float sanitize(float v) {
  return std::isfinite(v) && v > 0.0f ? v : 0.0f;
}
}  // namespace

double log_average_luminance(const cv::Mat& linear_rgb, double delta) {
  if (linear_rgb.type() != CV_32FC3)
    throw std::invalid_argument("log_average_luminance: need CV_32FC3");
  if (linear_rgb.empty()) return 0.0;
  // Summed per row first: the mean of ~10^7 logs in one double is fine, but the rows keep the
  // partial sums small.
  double total = 0.0;
  for (int y = 0; y < linear_rgb.rows; ++y) {
    const auto* row = linear_rgb.ptr<cv::Vec3f>(y);
    double s = 0.0;
    for (int x = 0; x < linear_rgb.cols; ++x) {
      const cv::Vec3f c(sanitize(row[x][0]), sanitize(row[x][1]), sanitize(row[x][2]));
      s += std::log(delta + luminance(c));
    }
    total += s;
  }
  return std::exp(total / static_cast<double>(linear_rgb.total()));
}

double srgb_encode(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

cv::Mat tone_map_reinhard(const cv::Mat& linear_rgb, const ToneMapSettings& settings) {
  if (linear_rgb.type() != CV_32FC3)
    throw std::invalid_argument("tone_map_reinhard: need CV_32FC3");
  const double l_avg = log_average_luminance(linear_rgb, settings.delta);
  const double scale = l_avg > 0.0 ? settings.key / l_avg : 0.0;
  cv::Mat out(linear_rgb.size(), CV_32FC3);
  for (int y = 0; y < linear_rgb.rows; ++y) {
    const auto* in = linear_rgb.ptr<cv::Vec3f>(y);
    auto* o = out.ptr<cv::Vec3f>(y);
    for (int x = 0; x < linear_rgb.cols; ++x) {
      const cv::Vec3f c(sanitize(in[x][0]), sanitize(in[x][1]), sanitize(in[x][2]));
      const double lw = luminance(c);
      if (!(lw > 0.0)) {
        o[x] = cv::Vec3f(0, 0, 0);
        continue;
      }
      const double l = scale * lw;
      const double ratio = (l / (1.0 + l)) / lw;
      for (int k = 0; k < 3; ++k) o[x][k] = static_cast<float>(srgb_encode(c[k] * ratio));
    }
  }
  return out;
}

}  // namespace vdfx::io
