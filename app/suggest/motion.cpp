/// @file
/// @brief Camera rotation from optical flow on the equirect (motion.h).
#include "app/suggest/motion.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <vector>

#include "app/suggest/greedy_fit.h"
#include "effects/coords.h"

namespace vdfx::app::suggest {

cv::Mat motion_frame(const cv::Mat& rgb, const MotionOptions& options) {
  cv::Mat grey, small;
  cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
  cv::resize(grey, small, cv::Size(options.width * options.coverage_deg / 360, options.width / 2),
             0, 0, cv::INTER_AREA);
  small.convertTo(grey, CV_8U, 255.0);
  return grey;
}

Eigen::Matrix3d kabsch(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  const Eigen::Matrix3d h = a * b.transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixV() * d * svd.matrixU().transpose();
}

namespace {

/// The direction of a point of a frame spanning `coverage` degrees of azimuth.
Eigen::Vector3d unit_at(const cv::Point2f& p, const cv::Size& size, int coverage) {
  const double az = (p.x / size.width - 0.5) * coverage, alt = 90.0 - 180.0 * p.y / size.height;
  return effects::to_unit({az, alt});
}

double angle_deg_of(const Eigen::Matrix3d& r) {
  return std::acos(std::clamp((r.trace() - 1.0) / 2.0, -1.0, 1.0)) * effects::kRadToDeg;
}

}  // namespace

Rotation estimate_rotation(const cv::Mat& grey_a, const cv::Mat& grey_b,
                           const MotionOptions& options) {
  const cv::Size size = grey_a.size();
  // Directions of the lattice inside the band, and 8 % of the width away from the seam (the
  // flow does not wrap around it).
  std::vector<cv::Point2f> from;
  const double margin = 0.08;
  const int lattice =
      static_cast<int>(options.points / std::sin(options.max_altitude_deg * effects::kDegToRad));
  for (const auto& d : sphere_directions(lattice)) {
    if (std::abs(d.altitude_deg) > options.max_altitude_deg) continue;
    const Eigen::Vector2d uv(0.5 + d.azimuth_deg / options.coverage_deg,
                             effects::to_equirect_uv(d).y());
    if (uv.x() < margin || uv.x() > 1.0 - margin) continue;
    from.emplace_back(static_cast<float>(uv.x() * size.width),
                      static_cast<float>(uv.y() * size.height));
  }
  std::vector<cv::Point2f> to;
  std::vector<unsigned char> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(grey_a, grey_b, from, to, status, error, cv::Size(21, 21), 4);
  std::vector<Eigen::Vector3d> a, b;
  for (std::size_t i = 0; i < from.size(); ++i) {
    if (!status[i] || to[i].x < 0 || to[i].y < 0 || to[i].x >= size.width || to[i].y >= size.height)
      continue;
    a.push_back(unit_at(from[i], size, options.coverage_deg));
    b.push_back(unit_at(to[i], size, options.coverage_deg));
  }
  Rotation out;
  if (a.size() < 8) return out;
  const auto solve = [](const std::vector<Eigen::Vector3d>& p,
                        const std::vector<Eigen::Vector3d>& q) {
    Eigen::Matrix3Xd pa(3, p.size()), qb(3, q.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      pa.col(static_cast<Eigen::Index>(i)) = p[i];
      qb.col(static_cast<Eigen::Index>(i)) = q[i];
    }
    return kabsch(pa, qb);
  };
  Eigen::Matrix3d r = solve(a, b);
  std::vector<double> residual(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) residual[i] = (r * a[i] - b[i]).norm();
  std::vector<double> sorted = residual;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double limit = std::max(3.0 * sorted[sorted.size() / 2], 1e-4);
  std::vector<Eigen::Vector3d> ka, kb;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (residual[i] <= limit) {
      ka.push_back(a[i]);
      kb.push_back(b[i]);
    }
  if (ka.size() >= 8) r = solve(ka, kb);
  out.matrix = r;
  out.angle_deg = angle_deg_of(r);
  out.tracked = static_cast<int>(ka.size() >= 8 ? ka.size() : a.size());
  return out;
}

std::vector<double> camera_motion_speeds(const effects::CameraMotion& camera, std::int64_t frames,
                                         double fps) {
  std::vector<double> speed(static_cast<std::size_t>(std::max<std::int64_t>(frames, 0)), 0.0);
  const auto n = static_cast<std::int64_t>(camera.orientation.size());
  if (n == 0 || speed.size() < 2) return speed;
  auto at = [&](std::int64_t f) {
    return effects::to_eigen(camera.orientation[static_cast<std::size_t>(std::min(f, n - 1))])
        .normalized();
  };
  for (std::int64_t f = 1; f < frames; ++f)
    speed[static_cast<std::size_t>(f)] =
        at(f - 1).angularDistance(at(f)) * effects::kRadToDeg * fps;
  speed[0] = speed[1];
  return speed;
}

}  // namespace vdfx::app::suggest
