/// @file
/// @brief Eye poses, projection and view matrices, optical centre and CPU camera description.
#include "xr/headset/eye_views.h"

#include <cmath>
#include <limits>

namespace vdfx::xr {

glm::dmat4 projection_from_fov(const FovDeg& fov, double near_z, double far_z, ClipDepth depth) {
  const effects::TanRect t = fov.tangents();
  glm::dmat4 m(0.0);  // m[column][row]
  // A view-space point (x, y, z) lies at tangent x/(-z); map [tL, tR] -> [-1, 1] linearly and let
  // the perspective divide by w = -z do the rest.
  m[0][0] = 2.0 / (t.right - t.left);
  m[2][0] = (t.right + t.left) / (t.right - t.left);
  m[1][1] = 2.0 / (t.up - t.down);
  m[2][1] = (t.up + t.down) / (t.up - t.down);
  m[2][3] = -1.0;
  // Depth: z_ndc = (A z + B) / (-z), with z = -near -> lowest, z = -far -> 1.
  const bool infinite = !(far_z > near_z);
  if (depth == ClipDepth::MinusOneToOne) {
    m[2][2] = infinite ? -1.0 : -(far_z + near_z) / (far_z - near_z);
    m[3][2] = infinite ? -2.0 * near_z : -2.0 * far_z * near_z / (far_z - near_z);
  } else {
    m[2][2] = infinite ? -1.0 : -far_z / (far_z - near_z);
    m[3][2] = infinite ? -near_z : -far_z * near_z / (far_z - near_z);
  }
  return m;
}

glm::dmat4 view_from_pose(const Pose& pose) {
  const glm::dmat3 r_t = glm::transpose(glm::mat3_cast(pose.orientation));
  glm::dmat4 v(r_t);
  v[3] = glm::dvec4(-(r_t * pose.position), 1.0);
  return v;
}

std::array<EyeView, 2> locate_eye_views(const Pose& head, const HmdProfile& profile, double near_z,
                                        double far_z) {
  std::array<EyeView, 2> views;
  for (const Eye e : kEyes) {
    EyeView& v = views[static_cast<int>(e)];
    const double half = 0.5 * profile.ipd_m * (e == Eye::Left ? -1.0 : 1.0);
    v.eye = e;
    v.pose.orientation = head.orientation;
    v.pose.position = head.position + head.orientation * glm::dvec3(half, 0.0, 0.0);
    v.fov = profile.eye(e).fov;
    v.view = view_from_pose(v.pose);
    v.projection = projection_from_fov(v.fov, near_z, far_z);
    v.width = profile.eye(e).width;
    v.height = profile.eye(e).height;
  }
  return views;
}

glm::dvec2 project_to_pixel(const EyeView& view, const glm::dvec3& world_point) {
  const glm::dvec4 clip = view.projection * view.view * glm::dvec4(world_point, 1.0);
  if (!(clip.w > 0.0)) return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
  const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
  return {0.5 * (ndc.x + 1.0) * view.width, 0.5 * (1.0 - ndc.y) * view.height};
}

glm::dvec2 optical_centre_px(const EyeView& view, const Pose& head) {
  const glm::dvec3 forward = head.orientation * glm::dvec3(0.0, 0.0, -1.0);
  return project_to_pixel(view, head.position + 10.0 * forward);
}

glm::dmat3 camera_rotation(const effects::Direction& look, double roll_deg) {
  const glm::dquat q = glm::angleAxis(-look.azimuth_deg * effects::kDegToRad, glm::dvec3(0, 1, 0)) *
                       glm::angleAxis(look.altitude_deg * effects::kDegToRad, glm::dvec3(1, 0, 0)) *
                       glm::angleAxis(roll_deg * effects::kDegToRad, glm::dvec3(0, 0, 1));
  return glm::mat3_cast(q);
}

EyeCamera eye_camera(const Pose& head, const HmdProfile& profile, Eye eye) {
  EyeCamera cam;
  cam.look = forward_direction(head);
  // Roll: the head's up axis measured in the roll-free camera frame of the same look direction.
  const glm::dmat3 r0 = camera_rotation(cam.look, 0.0);
  const glm::dvec3 up = head.orientation * glm::dvec3(0.0, 1.0, 0.0);
  cam.roll_deg = std::atan2(-glm::dot(up, r0[0]), glm::dot(up, r0[1])) * effects::kRadToDeg;
  const FovDeg& fov = profile.eye(eye).fov;
  cam.angle_left = fov.angle_left * effects::kDegToRad;
  cam.angle_right = fov.angle_right * effects::kDegToRad;
  cam.angle_up = fov.angle_up * effects::kDegToRad;
  cam.angle_down = fov.angle_down * effects::kDegToRad;
  cam.width = profile.eye(eye).width;
  cam.height = profile.eye(eye).height;
  return cam;
}

}  // namespace vdfx::xr
