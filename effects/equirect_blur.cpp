/// @file
/// @brief Angular Gaussian blur of equirect images (constant and per-pixel sigma).
#include "effects/equirect_blur.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace vdfx::effects {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Altitude (radians) of row y's texel centres in an image `h` rows high.
double row_altitude(int y, int h) {
  return 0.5 * kPi - (y + 0.5) * kPi / h;
}

/// The exact angular gather at this image's own resolution (sigma in radians).
cv::Mat gather(const cv::Mat& img, double sigma) {
  const int w = img.cols, h = img.rows;
  const double radius = 3.0 * sigma, cos_radius = std::cos(radius);
  const double dphi = kPi / h, dlam = 2.0 * kPi / w;
  std::vector<double> s(static_cast<std::size_t>(h)), c(static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    s[static_cast<std::size_t>(y)] = std::sin(row_altitude(y, h));
    c[static_cast<std::size_t>(y)] = std::cos(row_altitude(y, h));
  }
  const int reach = static_cast<int>(std::ceil(radius / dphi));
  cv::Mat out(h, w, CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    std::vector<float> acc(static_cast<std::size_t>(3 * w));
    std::vector<std::pair<int, float>> taps;
    for (int i = rows.start; i < rows.end; ++i) {
      std::fill(acc.begin(), acc.end(), 0.0f);
      double norm = 0.0;
      const double si = s[static_cast<std::size_t>(i)], ci = c[static_cast<std::size_t>(i)];
      for (int j = std::max(0, i - reach); j <= std::min(h - 1, i + reach); ++j) {
        const double sj = s[static_cast<std::size_t>(j)], cj = c[static_cast<std::size_t>(j)];
        // Widest column offset still within the radius: cos(dlambda) >= (cos R - si sj) / (ci cj).
        int k = w / 2;
        const double den = ci * cj;
        if (den > 1e-12) {
          const double q = (cos_radius - si * sj) / den;
          if (q >= 1.0) continue;  // this row is farther than the radius everywhere
          if (q > -1.0) k = std::min(k, static_cast<int>(std::floor(std::acos(q) / dlam)) + 1);
        }
        // Each column once: offsets -k..k, or every column of the row when that wraps.
        const int lo = 2 * k + 1 > w ? -(w / 2) : -k;
        const int hi = 2 * k + 1 > w ? w - 1 - w / 2 : k;
        taps.clear();
        for (int d = lo; d <= hi; ++d) {
          const double cos_theta = std::clamp(si * sj + ci * cj * std::cos(d * dlam), -1.0, 1.0);
          const double theta = std::acos(cos_theta);
          if (theta > radius) continue;
          const double wgt = std::exp(-theta * theta / (2.0 * sigma * sigma)) * cj;
          taps.emplace_back(d, static_cast<float>(wgt));
          norm += wgt;
        }
        const float* src = img.ptr<float>(j);
        for (const auto& [d, wgt] : taps) {
          // out[x] += wgt * src[(x + d) mod w]: two contiguous runs.
          const int shift = ((d % w) + w) % w;
          const int first = w - shift;  // x in [0, first) reads x + shift
          float* a = acc.data();
          const float* p = src + 3 * shift;
          for (int t = 0; t < 3 * first; ++t) a[t] += wgt * p[t];
          float* a2 = acc.data() + 3 * first;
          for (int t = 0; t < 3 * shift; ++t) a2[t] += wgt * src[t];
        }
      }
      float* dst = out.ptr<float>(i);
      const float inv = static_cast<float>(1.0 / norm);
      for (int t = 0; t < 3 * w; ++t) dst[t] = acc[static_cast<std::size_t>(t)] * inv;
    }
  });
  return out;
}

/// A blurred level (at a reduced resolution for large sigmas) and its sigma.
struct Level {
  cv::Mat image;
  double sigma_deg = 0.0;
};

/// Solid-angle weighted box reduction by `f`: each reduced texel is the average of its f x f
/// texels weighted by cos(altitude), so a reduced image holds the same light as the original.
cv::Mat reduce(const cv::Mat& rgb, int f) {
  const int h = rgb.rows;
  cv::Mat weighted = rgb.clone(), cosines(h, 1, CV_32FC1);
  for (int y = 0; y < h; ++y) {
    const float c = static_cast<float>(std::cos(row_altitude(y, h)));
    weighted.row(y) *= c;
    cosines.at<float>(y, 0) = c;
  }
  cv::Mat small, small_cos;
  cv::resize(weighted, small, cv::Size(rgb.cols / f, h / f), 0, 0, cv::INTER_AREA);
  cv::resize(cosines, small_cos, cv::Size(1, h / f), 0, 0, cv::INTER_AREA);
  for (int y = 0; y < small.rows; ++y) small.row(y) /= small_cos.at<float>(y, 0);
  return small;
}

/// blur_equirect at its reduced resolution (not sampled back). The reduction (a box of f texels)
/// and the bilinear read-back (a tent of f texels) blur too, by variances f^2/12 and f^2/6 (in
/// full-resolution texels): the gather's own sigma is smaller by that, so the whole chain has the
/// asked-for sigma. f is the largest power of two keeping sigma >= 1 reduced texel.
Level blurred_level(const cv::Mat& rgb, double sigma_deg) {
  const int w = rgb.cols, h = rgb.rows;
  const double texel_deg = 360.0 / w;
  const double sigma_px = sigma_deg / texel_deg;  // in texels at the equator
  int f = 1;
  while (sigma_px / (2 * f) >= 1.0 && w / (2 * f) >= 8 && h / (2 * f) >= 4) f *= 2;
  if (f == 1) return {gather(rgb, sigma_deg * kPi / 180.0), sigma_deg};
  const double gather_px = std::sqrt(sigma_px * sigma_px - 0.25 * f * f);
  return {gather(reduce(rgb, f), gather_px * texel_deg * kPi / 180.0), sigma_deg};
}

/// Bilinear sample of `level` at full-resolution pixel (x, y) of a w x h image (u wraps).
cv::Vec3f sample_level(const cv::Mat& level, int x, int y, int w, int h) {
  if (level.cols == w && level.rows == h) return level.at<cv::Vec3f>(y, x);
  const double lx = (x + 0.5) * level.cols / w - 0.5, ly = (y + 0.5) * level.rows / h - 0.5;
  const int x0 = static_cast<int>(std::floor(lx)), y0 = static_cast<int>(std::floor(ly));
  const float fx = static_cast<float>(lx - x0), fy = static_cast<float>(ly - y0);
  const int xa = ((x0 % level.cols) + level.cols) % level.cols, xb = (xa + 1) % level.cols;
  const int ya = std::clamp(y0, 0, level.rows - 1), yb = std::clamp(y0 + 1, 0, level.rows - 1);
  const cv::Vec3f top = level.at<cv::Vec3f>(ya, xa) * (1 - fx) + level.at<cv::Vec3f>(ya, xb) * fx;
  const cv::Vec3f bottom =
      level.at<cv::Vec3f>(yb, xa) * (1 - fx) + level.at<cv::Vec3f>(yb, xb) * fx;
  return top * (1 - fy) + bottom * fy;
}

void check_input(const cv::Mat& rgb) {
  if (rgb.empty() || rgb.type() != CV_32FC3)
    throw std::invalid_argument("equirect blur: a CV_32FC3 image expected");
}

}  // namespace

cv::Mat blur_equirect(const cv::Mat& rgb, double sigma_deg) {
  check_input(rgb);
  if (!(sigma_deg > 0.0)) return rgb.clone();
  const Level level = blurred_level(rgb, sigma_deg);
  if (level.image.size() == rgb.size()) return level.image;
  cv::Mat out(rgb.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y)
      for (int x = 0; x < rgb.cols; ++x)
        out.at<cv::Vec3f>(y, x) = sample_level(level.image, x, y, rgb.cols, rgb.rows);
  });
  return out;
}

cv::Mat blur_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg, double ratio) {
  check_input(rgb);
  if (sigma_deg.size() != rgb.size() || sigma_deg.type() != CV_32FC1)
    throw std::invalid_argument(
        "equirect blur: the sigma map must be CV_32FC1 of the image's size");
  if (!(ratio > 1.0)) throw std::invalid_argument("equirect blur: level ratio must exceed 1");
  double max_sigma = 0.0;
  cv::minMaxLoc(sigma_deg, nullptr, &max_sigma);
  if (!(max_sigma > 0.0)) return rgb.clone();
  const int w = rgb.cols, h = rgb.rows;
  // Level 0 is the image itself (sigma 0); then half a texel, growing by `ratio`.
  std::vector<Level> levels{{rgb, 0.0}};
  for (double s = 0.5 * 360.0 / w;; s *= ratio) {
    levels.push_back(blurred_level(rgb, s));
    if (s >= max_sigma) break;
  }
  cv::Mat out(rgb.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const float* sig = sigma_deg.ptr<float>(y);
      cv::Vec3f* dst = out.ptr<cv::Vec3f>(y);
      for (int x = 0; x < w; ++x) {
        const double s = std::max(0.0f, sig[x]);
        if (s <= 0.0) {
          dst[x] = rgb.at<cv::Vec3f>(y, x);
          continue;
        }
        std::size_t k = 1;
        while (k + 1 < levels.size() && levels[k].sigma_deg < s) ++k;
        const Level& a = levels[k - 1];
        const Level& b = levels[k];
        const float t = static_cast<float>(
            std::clamp((s - a.sigma_deg) / (b.sigma_deg - a.sigma_deg), 0.0, 1.0));
        dst[x] =
            sample_level(a.image, x, y, w, h) * (1.0f - t) + sample_level(b.image, x, y, w, h) * t;
      }
    }
  });
  return out;
}

}  // namespace vdfx::effects
