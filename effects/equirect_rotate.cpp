/// @file
/// @brief rotate_equirect (equirect_rotate.h).
#include "effects/equirect_rotate.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "effects/coords.h"

namespace vdfx::effects {

void rotate_equirect(const cv::Mat& src, const Eigen::Matrix3d& r, cv::Mat& out, int coverage_deg) {
  const int w = src.cols, h = src.rows;
  const double span = coverage_deg * kDegToRad;
  const Eigen::Matrix3d rt = r.transpose();
  cv::Mat map_x(h, w, CV_32F), map_y(h, w, CV_32F);
  // Each column's azimuth once (its sine and cosine), then per row: the turned direction.
  std::vector<double> sin_az(static_cast<std::size_t>(w)), cos_az(static_cast<std::size_t>(w));
  for (int x = 0; x < w; ++x) {
    const double az = ((x + 0.5) / w - 0.5) * span;
    sin_az[static_cast<std::size_t>(x)] = std::sin(az);
    cos_az[static_cast<std::size_t>(x)] = std::cos(az);
  }
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const double alt = (0.5 - (y + 0.5) / h) * kPi;
      const double ca = std::cos(alt), sa = std::sin(alt);
      auto* mx = map_x.ptr<float>(y);
      auto* my = map_y.ptr<float>(y);
      for (int x = 0; x < w; ++x) {
        const auto i = static_cast<std::size_t>(x);
        const Eigen::Vector3d a = rt * Eigen::Vector3d(ca * sin_az[i], sa, -ca * cos_az[i]);
        const double src_az = std::atan2(a.x(), -a.z());
        const double src_alt = std::atan2(a.y(), std::hypot(a.x(), a.z()));
        // remap's coordinates put pixel centres on integers. Rows are clamped to the image's
        // (at the poles the first or last row), so that only columns wrap.
        mx[x] = static_cast<float>((src_az / span + 0.5) * w - 0.5);
        my[x] = static_cast<float>(std::clamp((0.5 - src_alt / kPi) * h - 0.5, 0.0, h - 1.0));
      }
    }
  });
  cv::remap(src, out, map_x, map_y, cv::INTER_LINEAR,
            coverage_deg == 360 ? cv::BORDER_WRAP : cv::BORDER_CONSTANT, cv::Scalar::all(0));
}

}  // namespace vdfx::effects
