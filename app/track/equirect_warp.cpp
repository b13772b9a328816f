/// @file
/// @brief warp_equirect and pad_for_flow (equirect_warp.h).
#include "app/track/equirect_warp.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "effects/coords.h"

namespace vdfx::app::track {
namespace {

// The map is computed exactly every kStep pixels and interpolated bilinearly between: the
// spherical coordinates of a turned direction are smooth away from the source's poles (no
// corner is followed there), and the exact form (two arctangents a pixel) cost more than the
// rest of a key frame's match together.
constexpr int kStep = 4;

struct MapPoint {
  double x, y;
};

}  // namespace

cv::Mat warp_equirect(const cv::Mat& grey, const SphereGrid& grid, const Eigen::Matrix3d& r) {
  const Eigen::Matrix3d rt = r.transpose();
  const double to_x = grid.width / (grid.coverage_deg * effects::kDegToRad);
  const double to_y = grid.height / effects::kPi;
  // The exact source position (remap's pixel-centre coordinates) of output position (x, y).
  const auto exact = [&](double x, double y) {
    const double alt = (0.5 - y / grid.height) * effects::kPi;
    const double az = (x / grid.width - 0.5) * grid.coverage_deg * effects::kDegToRad;
    const Eigen::Vector3d c(std::cos(alt) * std::sin(az), std::sin(alt),
                            -std::cos(alt) * std::cos(az));
    const Eigen::Vector3d a = rt * c;
    const double src_az = std::atan2(a.x(), -a.z());
    const double src_alt = std::atan2(a.y(), std::hypot(a.x(), a.z()));
    return MapPoint{src_az * to_x + 0.5 * grid.width - 0.5,
                    (0.5 * effects::kPi - src_alt) * to_y - 0.5};
  };
  const int nx = grid.width / kStep + 2, ny = grid.height / kStep + 2;
  std::vector<MapPoint> nodes(static_cast<std::size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      nodes[static_cast<std::size_t>(j * nx + i)] = exact(i * kStep + 0.5, j * kStep + 0.5);
  cv::Mat map_x(grid.height, grid.width, CV_32F), map_y(grid.height, grid.width, CV_32F);
  const double w = grid.width, half = 0.5 * w;
  for (int y = 0; y < grid.height; ++y) {
    const int j = y / kStep;
    const double fy = static_cast<double>(y % kStep) / kStep;
    auto* mx = map_x.ptr<float>(y);
    auto* my = map_y.ptr<float>(y);
    for (int i = 0; i * kStep < grid.width; ++i) {
      const MapPoint& p00 = nodes[static_cast<std::size_t>(j * nx + i)];
      MapPoint q[4] = {p00, nodes[static_cast<std::size_t>(j * nx + i + 1)],
                       nodes[static_cast<std::size_t>((j + 1) * nx + i)],
                       nodes[static_cast<std::size_t>((j + 1) * nx + i + 1)]};
      // Across the source's seam x jumps by a turn: unwrap round the first corner (remap wraps
      // what falls outside for a 360 image).
      for (MapPoint& p : q)
        if (p.x - p00.x > half)
          p.x -= w;
        else if (p00.x - p.x > half)
          p.x += w;
      for (int k = 0; k < kStep && i * kStep + k < grid.width; ++k) {
        const double fx = static_cast<double>(k) / kStep;
        const double top_x = q[0].x + fx * (q[1].x - q[0].x),
                     bot_x = q[2].x + fx * (q[3].x - q[2].x);
        const double top_y = q[0].y + fx * (q[1].y - q[0].y),
                     bot_y = q[2].y + fx * (q[3].y - q[2].y);
        mx[i * kStep + k] = static_cast<float>(top_x + fy * (bot_x - top_x));
        my[i * kStep + k] = static_cast<float>(top_y + fy * (bot_y - top_y));
      }
    }
  }
  cv::Mat out;
  cv::remap(grey, out, map_x, map_y, cv::INTER_LINEAR,
            grid.wraps() ? cv::BORDER_WRAP : cv::BORDER_CONSTANT, cv::Scalar(0));
  return out;
}

cv::Mat pad_for_flow(const cv::Mat& grey, const SphereGrid& grid, int pad) {
  cv::Mat wide, out;
  cv::copyMakeBorder(grey, wide, 0, 0, pad, pad,
                     grid.wraps() ? cv::BORDER_WRAP : cv::BORDER_REPLICATE);
  cv::copyMakeBorder(wide, out, pad, pad, 0, 0, cv::BORDER_REPLICATE);
  return out;
}

}  // namespace vdfx::app::track
