/// @file
/// @brief CPU reference of the flare layer.
#include "effects/flare_render.h"

#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

Eigen::Vector3d flare_at_ray(const FlareLayout& layout, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& ray) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const double denom = layout.normal.dot(ray);
  if (denom == 0.0) return sum;
  const double t = layout.normal.dot(layout.light_point - eye) / denom;
  if (!(t > 0.0)) return sum;  // the plane is behind this eye along the ray
  const Eigen::Vector3d hit = eye + t * ray;
  for (const FlareElement& e : layout.elements) {
    // In-plane coordinates, as the GL quad interpolates them (no normal component).
    const Eigen::Vector3d q = hit - e.centre;
    const double rho = std::hypot(q.dot(layout.axis_u), q.dot(layout.axis_v)) / e.radius;
    if (rho < element_support(e)) sum += element_profile(e, rho);
  }
  return sum;
}

void add_flares(cv::Mat& rgb, const ViewCamera& camera, const Eigen::Vector3d& eye,
                std::span<const FlareLayout> layouts) {
  if (rgb.type() != CV_32FC3 || rgb.cols != camera.width() || rgb.rows != camera.height())
    throw std::invalid_argument("add_flares: expected a CV_32FC3 image of the camera's size");
  if (layouts.empty()) return;
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      auto* row = rgb.ptr<cv::Vec3f>(j);
      for (int i = 0; i < rgb.cols; ++i) {
        const Eigen::Vector3d ray = camera.pixel_ray(i, j);
        Eigen::Vector3d add = Eigen::Vector3d::Zero();
        for (const FlareLayout& l : layouts) add += flare_at_ray(l, eye, ray);
        for (int c = 0; c < 3; ++c) row[i][c] = static_cast<float>(row[i][c] + add[c]);
      }
    }
  });
}

}  // namespace vdfx::effects
