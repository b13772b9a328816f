/// @file
/// @brief ViewCamera: pinhole rays and projection.
#include "effects/view_camera.h"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vdfx::effects {

Eigen::Matrix3d pose_rotation(const ViewPose& pose) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  return (Eigen::AngleAxisd(-pose.look.azimuth_deg * kDegToRad, y) *
          Eigen::AngleAxisd(pose.look.altitude_deg * kDegToRad, x) *
          Eigen::AngleAxisd(pose.roll_deg * kDegToRad, z))
      .toRotationMatrix();
}

namespace {
void check_size(int width, int height, const char* where) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument(std::string(where) + ": image size must be positive, got " +
                                std::to_string(width) + "x" + std::to_string(height));
}
}  // namespace

ViewCamera ViewCamera::from_horizontal_fov(const ViewPose& pose, double hfov_deg, int width,
                                           int height) {
  check_size(width, height, "ViewCamera::from_horizontal_fov");
  if (!(hfov_deg > 0.0 && hfov_deg < 180.0))
    throw std::invalid_argument(
        "ViewCamera::from_horizontal_fov: fov must be in (0, 180) degrees, got " +
        std::to_string(hfov_deg));
  const double f = 0.5 * width / std::tan(0.5 * hfov_deg * kDegToRad);
  return ViewCamera(pose_rotation(pose), f, f, 0.5 * width, 0.5 * height, width, height);
}

TanRect FovAngles::tangents() const {
  const double half = 0.5 * kPi;
  const bool inside = std::abs(angle_left) < half && std::abs(angle_right) < half &&
                      std::abs(angle_up) < half && std::abs(angle_down) < half;
  if (!inside || !(angle_right > angle_left) || !(angle_up > angle_down))
    throw std::invalid_argument(
        "FovAngles: need -pi/2 < left < right < pi/2 and -pi/2 < down < up < pi/2");
  return {std::tan(angle_left), std::tan(angle_right), std::tan(angle_up), std::tan(angle_down)};
}

ViewCamera ViewCamera::from_fov_angles(const ViewPose& pose, const FovAngles& fov, int width,
                                       int height) {
  check_size(width, height, "ViewCamera::from_fov_angles");
  return from_tangents(pose_rotation(pose), fov.tangents(), width, height);
}

ViewCamera ViewCamera::from_tangents(const Eigen::Matrix3d& camera_to_world, const TanRect& fov,
                                     int width, int height) {
  check_size(width, height, "ViewCamera::from_tangents");
  if (!(fov.right > fov.left) || !(fov.up > fov.down) || !std::isfinite(fov.right - fov.left) ||
      !std::isfinite(fov.up - fov.down))
    throw std::invalid_argument(
        "ViewCamera::from_tangents: need left < right and down < up, finite");
  const double fx = width / (fov.right - fov.left), fy = height / (fov.up - fov.down);
  return ViewCamera(camera_to_world, fx, fy, -fov.left * fx, fov.up * fy, width, height);
}

ViewCamera::ViewCamera(const Eigen::Matrix3d& camera_to_world, double fx, double fy, double cx,
                       double cy, int width, int height)
    : rotation_(camera_to_world),
      fx_(fx),
      fy_(fy),
      cx_(cx),
      cy_(cy),
      width_(width),
      height_(height) {
  check_size(width, height, "ViewCamera");
  if (!(fx > 0.0 && fy > 0.0 && std::isfinite(fx) && std::isfinite(fy)))
    throw std::invalid_argument("ViewCamera: focal lengths must be positive and finite");
}

Eigen::Vector3d ViewCamera::ray(double x, double y) const {
  const Eigen::Vector2d t = tangent(x, y);
  return (rotation_ * Eigen::Vector3d(t.x(), t.y(), -1.0)).normalized();
}

std::optional<Eigen::Vector2d> ViewCamera::project(const Eigen::Vector3d& world_dir) const {
  const Eigen::Vector3d cam = rotation_.transpose() * world_dir;
  if (!(cam.z() < 0.0)) return std::nullopt;
  const double depth = -cam.z();
  return pixel_of_tangent({cam.x() / depth, cam.y() / depth});
}

ViewCamera ViewCamera::with_margin(int margin) const {
  if (margin < 0) throw std::invalid_argument("ViewCamera::with_margin: negative margin");
  return ViewCamera(rotation_, fx_, fy_, cx_ + margin, cy_ + margin, width_ + 2 * margin,
                    height_ + 2 * margin);
}

}  // namespace vdfx::effects
