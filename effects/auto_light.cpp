/// @file
/// @brief Brightest-region measurement and the windowed track fit.
#include "effects/auto_light.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "effects/coords.h"
#include "effects/effect_types.h"

namespace vdfx::effects {

namespace {

// Smoothing before the peak search, in grid cells (1.4 degrees at 256 x 128): a plateau of
// clipped pixels up to several degrees wide then peaks strictly at its centre.
constexpr int kPeakSigmaCells = 2;

Eigen::Vector3d cell_direction(int i, int j, int w, int h) {
  return to_unit(from_equirect_uv({(i + 0.5) / w, (j + 0.5) / h}));
}

}  // namespace

std::optional<Eigen::Vector3d> find_brightest_region(const cv::Mat& rgb,
                                                     const AutoLightOptions& o) {
  if (rgb.empty()) return std::nullopt;
  if (rgb.type() != CV_32FC3 && rgb.type() != CV_8UC3)
    throw std::invalid_argument(
        "find_brightest_region: expected a CV_32FC3 or CV_8UC3 RGB equirect");
  const int w = std::max(8, o.grid_width), h = w / 2;
  cv::Mat small;
  cv::resize(rgb, small, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  if (small.type() == CV_8UC3) small.convertTo(small, CV_32FC3, 1.0 / 255.0);
  cv::Mat luma(h, w, CV_64F);
  std::vector<double> row_weight(static_cast<std::size_t>(h));
  double weight_sum = 0.0, luma_sum = 0.0;
  for (int j = 0; j < h; ++j) {
    row_weight[static_cast<std::size_t>(j)] = std::cos((0.5 - (j + 0.5) / h) * kPi);
    const auto* s = small.ptr<cv::Vec3f>(j);
    auto* y = luma.ptr<double>(j);
    for (int i = 0; i < w; ++i) {
      // NaN or negative input (a broken HDR frame) must not win the maximum or the sort.
      const double v = kLumaR * s[i][0] + kLumaG * s[i][1] + kLumaB * s[i][2];
      y[i] = std::isfinite(v) ? std::max(v, 0.0) : 0.0;
      weight_sum += row_weight[static_cast<std::size_t>(j)];
      luma_sum += row_weight[static_cast<std::size_t>(j)] * y[i];
    }
  }
  const double frame_mean = luma_sum / weight_sum;

  // Top set by solid angle: the brightest cells until top_fraction of the sphere is covered.
  std::vector<int> order(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  std::iota(order.begin(), order.end(), 0);
  const double* y = luma.ptr<double>(0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return y[a] > y[b]; });
  // Membership by rank, not by value: cells tied with the threshold beyond the top set (a flat
  // background) stay out of it.
  std::vector<unsigned char> top(order.size(), 0);
  double covered = 0.0, tau = 0.0;
  for (int idx : order) {
    covered += row_weight[static_cast<std::size_t>(idx / w)];
    tau = y[idx];
    top[static_cast<std::size_t>(idx)] = 1;
    if (covered >= o.top_fraction * weight_sum) break;
  }

  // Peak of the smoothed luma; azimuth wraps, so pad columns from the other side first.
  const int pad = 3 * kPeakSigmaCells;
  cv::Mat padded, smooth;
  cv::copyMakeBorder(luma, padded, 0, 0, pad, pad, cv::BORDER_WRAP);
  cv::GaussianBlur(padded, smooth, cv::Size(2 * pad + 1, 2 * pad + 1), kPeakSigmaCells,
                   kPeakSigmaCells, cv::BORDER_REPLICATE);
  cv::Point peak;
  cv::minMaxLoc(smooth(cv::Rect(pad, 0, w, h)), nullptr, nullptr, nullptr, &peak);
  const Eigen::Vector3d peak_dir = cell_direction(peak.x, peak.y, w, h);

  const double cos_region = std::cos(o.region_deg * kDegToRad);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), plateau = Eigen::Vector3d::Zero();
  double region_luma = 0.0, region_weight = 0.0, region_max = 0.0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const double v = y[j * w + i];
      if (v < tau) continue;
      const Eigen::Vector3d n = cell_direction(i, j, w, h);
      if (n.dot(peak_dir) < cos_region) continue;
      const double sa = row_weight[static_cast<std::size_t>(j)];
      plateau += sa * n;  // every cell at or above tau, ties included
      if (!top[static_cast<std::size_t>(j * w + i)]) continue;
      centroid += sa * (v - tau) * n;
      region_luma += sa * v;
      region_weight += sa;
      region_max = std::max(region_max, v);
    }
  }
  if (region_weight <= 0.0) return std::nullopt;
  if (region_max < o.min_luma) return std::nullopt;
  if (region_luma / region_weight < o.min_contrast * frame_mean) return std::nullopt;
  // A clipped plateau wider than the top set has every top cell at tau (which of the tied cells
  // made the top set is arbitrary): its centre by area over all of its cells near the peak.
  if (centroid.norm() == 0.0) centroid = plateau;
  if (centroid.norm() == 0.0) return std::nullopt;
  return centroid.normalized();
}

void AutoLightTracker::observe(std::int64_t frame, const cv::Mat& rgb) {
  // A frame measured before keeps its measurement; record() still marks it the latest shown.
  record(frame, observed(frame) ? std::nullopt : find_brightest_region(rgb, options()));
}

}  // namespace vdfx::effects
