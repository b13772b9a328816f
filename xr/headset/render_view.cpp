/// @file
/// @brief RenderView: pixel <-> tangent <-> ray.
#include "xr/headset/render_view.h"

#include <cmath>

#include "effects/view_camera.h"

namespace vdfx::xr {

using effects::kDegToRad;

RenderView RenderView::from_angles(const Eigen::Matrix3d& orientation, double angle_left,
                                   double angle_right, double angle_down, double angle_up) {
  const effects::TanRect t =
      effects::FovAngles{angle_left, angle_right, angle_up, angle_down}.tangents();
  RenderView v;
  v.orientation = orientation;
  v.tan_left = t.left;
  v.tan_right = t.right;
  v.tan_down = t.down;
  v.tan_up = t.up;
  return v;
}

Eigen::Matrix3d view_rotation(const effects::Direction& d, double roll_deg) {
  return effects::pose_rotation({d, roll_deg});
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

effects::ViewCamera RenderView::camera(int width, int height) const {
  return effects::ViewCamera::from_tangents(orientation, tangents(), width, height);
}

Eigen::Vector2d RenderView::tangent_at(double px, double py, int width, int height) const {
  return camera(width, height).tangent(px, py);
}

Eigen::Vector2d RenderView::pixel_at(const Eigen::Vector2d& t, int width, int height) const {
  return camera(width, height).pixel_of_tangent(t);
}

Eigen::Vector3d RenderView::world_ray(double px, double py, int width, int height) const {
  return camera(width, height).ray(px, py);
}

Eigen::Matrix4d RenderView::projection(double n, double f) const {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  const double w = tan_right - tan_left, h = tan_up - tan_down;
  p(0, 0) = 2.0 / w;
  p(0, 2) = (tan_right + tan_left) / w;
  p(1, 1) = 2.0 / h;
  p(1, 2) = (tan_up + tan_down) / h;
  const bool infinite = !(f > n);
  p(2, 2) = infinite ? -1.0 : -(f + n) / (f - n);
  p(2, 3) = infinite ? -2.0 * n : -2.0 * f * n / (f - n);
  p(3, 2) = -1.0;
  return p;
}

Eigen::Matrix4d RenderView::world_to_eye() const {
  Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
  v.topLeftCorner<3, 3>() = orientation.transpose();
  v.topRightCorner<3, 1>() = -orientation.transpose() * position;
  return v;
}

}  // namespace vdfx::xr
