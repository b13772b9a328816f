/// @file
/// @brief RenderView: pixel <-> tangent <-> ray.
#include "xr/render_view.h"

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

}  // namespace vdfx::xr
