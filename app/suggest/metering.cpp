/// @file
/// @brief The metering model (metering.h); the transfer functions' constants are those of ITU-R
/// BT.1886, IEC 61966-2-1, SMPTE ST 2084 and ARIB STD-B67 as ITU-R BT.2100 states them.
#include "app/suggest/metering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "effects/coords.h"

namespace vdfx::app::suggest {

Transfer transfer_of(std::string_view name, bool is_still) {
  if (name == "iec61966-2-1") return Transfer::Srgb;
  if (name == "smpte2084") return Transfer::Pq;
  if (name == "arib-std-b67") return Transfer::Hlg;
  if (name == "linear") return Transfer::Linear;
  if (name.empty() && is_still) return Transfer::Srgb;
  return Transfer::Bt1886;
}

std::string_view transfer_name(Transfer transfer) {
  switch (transfer) {
    case Transfer::Bt1886: return "BT.1886 (gamma 2.4)";
    case Transfer::Srgb: return "sRGB";
    case Transfer::Pq: return "PQ (SMPTE ST 2084)";
    case Transfer::Hlg: return "HLG (ARIB STD-B67)";
    case Transfer::Linear: return "linear";
  }
  return "?";
}

double to_linear(double e, Transfer transfer) {
  e = std::clamp(e, 0.0, 1.0);
  switch (transfer) {
    case Transfer::Bt1886: return std::pow(e, 2.4);
    case Transfer::Srgb: return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
    case Transfer::Pq: {
      constexpr double m1 = 2610.0 / 16384.0, m2 = 2523.0 / 4096.0 * 128.0;
      constexpr double c1 = 3424.0 / 4096.0, c2 = 2413.0 / 4096.0 * 32.0,
                       c3 = 2392.0 / 4096.0 * 32.0;
      const double p = std::pow(e, 1.0 / m2);
      // 1.0 of the PQ signal is 10000 cd/m^2; vdfx's 1.0 is 100 cd/m^2.
      return 100.0 * std::pow(std::max(p - c1, 0.0) / (c2 - c3 * p), 1.0 / m1);
    }
    case Transfer::Hlg: {
      constexpr double a = 0.17883277, b = 1.0 - 4.0 * a, c = 0.55991073;
      return e <= 0.5 ? e * e / 3.0 : (std::exp((e - c) / a) + b) / 12.0;
    }
    case Transfer::Linear: return e;
  }
  return e;
}

MeterGeometry::MeterGeometry(int grid_width)
    : width_(grid_width),
      units_(3, grid_width * (grid_width / 2)),
      solid_angles_(grid_width * (grid_width / 2)) {
  if (grid_width < 4 || grid_width % 2 != 0)
    throw std::invalid_argument("metering grid width must be even and at least 4");
  const int h = height();
  const double d_az = 2.0 * effects::kPi / width_, d_alt = effects::kPi / h;
  for (int j = 0; j < h; ++j) {
    // Exact solid angle of the cell's band, split evenly between its cells.
    const double top = effects::kPi / 2 - j * d_alt, bottom = top - d_alt;
    const double band = d_az * (std::sin(top) - std::sin(bottom));
    for (int i = 0; i < width_; ++i) {
      const Eigen::Vector2d uv((i + 0.5) / width_, (j + 0.5) / h);
      units_.col(j * width_ + i) = effects::to_unit(effects::from_equirect_uv(uv));
      solid_angles_[j * width_ + i] = band;
    }
  }
}

namespace {

/// Linear luminance of every pixel of a CV_32FC3 image of display values.
cv::Mat linear_luma(const cv::Mat& rgb, Transfer transfer) {
  // Linear light per pixel first (area averages of encoded values would under-read highlights),
  // through a 4096-entry table per transfer: 12 bits is finer than any 10-bit master.
  constexpr int kTable = 4096;
  std::array<float, kTable + 1> lut{};
  for (int k = 0; k <= kTable; ++k)
    lut[k] = static_cast<float>(to_linear(static_cast<double>(k) / kTable, transfer));
  cv::Mat luma(rgb.size(), CV_32FC1);
  for (int y = 0; y < rgb.rows; ++y) {
    const auto* in = rgb.ptr<cv::Vec3f>(y);
    auto* out = luma.ptr<float>(y);
    for (int x = 0; x < rgb.cols; ++x) {
      const auto lin = [&](float v) {
        return lut[static_cast<int>(std::clamp(v, 0.0f, 1.0f) * kTable + 0.5f)];
      };
      out[x] = 0.2126f * lin(in[x][0]) + 0.7152f * lin(in[x][1]) + 0.0722f * lin(in[x][2]);
    }
  }
  return luma;
}

}  // namespace

LumaGrid make_luma_grid(const cv::Mat& rgb, Transfer transfer, const MeterGeometry& geometry,
                        const MeteringOptions& options, std::int64_t frame, int coverage_deg) {
  if (rgb.type() != CV_32FC3) throw std::invalid_argument("make_luma_grid wants CV_32FC3");
  if (coverage_deg != 360 && (coverage_deg != 180 || geometry.width() % 4 != 0))
    throw std::invalid_argument("make_luma_grid: coverage 360, or 180 on a grid 4k cells wide");
  // The image's cells: every column, or for VR180 the middle half (azimuth -90..90).
  const int cols = geometry.width() * coverage_deg / 360, first = (geometry.width() - cols) / 2;
  cv::Mat small;
  cv::resize(linear_luma(rgb, transfer), small, cv::Size(cols, geometry.height()), 0, 0,
             cv::INTER_AREA);
  LumaGrid grid;
  grid.frame = frame;
  const Eigen::Index cells = geometry.width() * geometry.height();
  grid.log2_luma = Eigen::VectorXd::Constant(cells, std::log2(options.floor));
  if (cols != geometry.width()) grid.covered = Eigen::VectorXd::Zero(cells);
  for (int y = 0; y < small.rows; ++y)
    for (int x = 0; x < small.cols; ++x) {
      const double v = small.at<float>(y, x);
      const Eigen::Index i = y * geometry.width() + first + x;
      grid.max_luma = std::max(grid.max_luma, v);
      grid.log2_luma[i] = std::log2(std::max(v, options.floor));
      if (grid.covered.size()) grid.covered[i] = 1.0;
    }
  return grid;
}

double metered_level(const LumaGrid& grid, const MeterGeometry& geometry,
                     const Eigen::Vector3d& view, const MeteringOptions& options) {
  const double half = 0.5 * options.fov_deg * effects::kDegToRad;
  const double sigma = 0.25 * options.fov_deg * effects::kDegToRad;
  const double cos_half = std::cos(half);
  const Eigen::VectorXd dots = geometry.units().transpose() * view;
  double sum = 0.0, weights = 0.0;
  for (Eigen::Index i = 0; i < dots.size(); ++i) {
    if (dots[i] < cos_half) continue;
    const double theta = std::acos(std::min(1.0, dots[i]));
    const double w = grid.weight(geometry, i) * std::exp(-theta * theta / (2 * sigma * sigma));
    sum += w * grid.log2_luma[i];
    weights += w;
  }
  // The field of view always holds cells (the grid is finer than any metered field, and a view
  // is only metered inside the image's coverage); guard anyway.
  return weights > 0.0 ? sum / weights : grid.log2_luma.mean();
}

double reference_level(std::span<const LumaGrid> grids, const MeterGeometry& geometry) {
  double sum = 0.0, weights = 0.0;
  for (const LumaGrid& g : grids)
    for (Eigen::Index i = 0; i < g.log2_luma.size(); ++i) {
      sum += g.weight(geometry, i) * g.log2_luma[i];
      weights += g.weight(geometry, i);
    }
  return weights > 0.0 ? sum / weights : 0.0;
}

}  // namespace vdfx::app::suggest
