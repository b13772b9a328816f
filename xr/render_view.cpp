/// @file
/// @brief RenderView: pixel <-> tangent <-> ray.
#include "xr/render_view.h"

#include <cmath>

namespace vdfx::xr {

using effects::kDegToRad;

RenderView RenderView::from_angles(const Eigen::Matrix3d& orientation, double angle_left,
                                   double angle_right, double angle_down, double angle_up) {
  RenderView v;
  v.orientation = orientation;
  v.tan_left = std::tan(angle_left);
  v.tan_right = std::tan(angle_right);
  v.tan_down = std::tan(angle_down);
  v.tan_up = std::tan(angle_up);
  return v;
}

Eigen::Matrix3d view_rotation(const effects::Direction& d, double roll_deg) {
  // Yaw about +y by -azimuth turns -z towards +x for positive azimuth; pitch about +x by altitude
  // lifts it; a camera rolled counter-clockwise about its forward axis (+z rotation) sees the
  // world turned clockwise, which is the contract's positive roll.
  return (Eigen::AngleAxisd(-d.azimuth_deg * kDegToRad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(d.altitude_deg * kDegToRad, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(roll_deg * kDegToRad, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

RenderView RenderView::look_at(const effects::Direction& d, double roll_deg, double hfov_deg,
                               int width, int height) {
  RenderView v;
  v.orientation = view_rotation(d, roll_deg);
  const double tx = std::tan(0.5 * hfov_deg * kDegToRad);
  const double ty = tx * static_cast<double>(height) / static_cast<double>(width);
  v.tan_left = -tx;
  v.tan_right = tx;
  v.tan_down = -ty;
  v.tan_up = ty;
  return v;
}

Eigen::Vector2d RenderView::tangent_at(double px, double py, int width, int height) const {
  return {tan_left + px / width * (tan_right - tan_left), tan_up - py / height * (tan_up - tan_down)};
}

Eigen::Vector2d RenderView::pixel_at(const Eigen::Vector2d& t, int width, int height) const {
  return {(t.x() - tan_left) / (tan_right - tan_left) * width,
          (tan_up - t.y()) / (tan_up - tan_down) * height};
}

Eigen::Vector3d RenderView::world_ray(double px, double py, int width, int height) const {
  const Eigen::Vector2d t = tangent_at(px, py, width, height);
  return (orientation * Eigen::Vector3d(t.x(), t.y(), -1.0)).normalized();
}

}  // namespace vdfx::xr
