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
    throw std::invalid_argument("ViewCamera::from_horizontal_fov: fov must be in (0, 180) degrees, got " +
                                std::to_string(hfov_deg));
  const double f = 0.5 * width / std::tan(0.5 * hfov_deg * kDegToRad);
  return ViewCamera(pose_rotation(pose), f, f, 0.5 * width, 0.5 * height, width, height);
}

ViewCamera ViewCamera::from_fov_angles(const ViewPose& pose, const FovAngles& fov, int width,
                                       int height) {
  check_size(width, height, "ViewCamera::from_fov_angles");
  const double l = std::tan(fov.angle_left), r = std::tan(fov.angle_right);
  const double u = std::tan(fov.angle_up), d = std::tan(fov.angle_down);
  const double half = 0.5 * kPi;
  const bool inside = std::abs(fov.angle_left) < half && std::abs(fov.angle_right) < half &&
                      std::abs(fov.angle_up) < half && std::abs(fov.angle_down) < half;
  if (!inside || !(r > l) || !(u > d))
    throw std::invalid_argument(
        "ViewCamera::from_fov_angles: need -pi/2 < left < right < pi/2 and -pi/2 < down < up < pi/2");
  const double fx = width / (r - l), fy = height / (u - d);
  return ViewCamera(pose_rotation(pose), fx, fy, -l * fx, u * fy, width, height);
}

ViewCamera::ViewCamera(const Eigen::Matrix3d& camera_to_world, double fx, double fy, double cx,
                       double cy, int width, int height)
    : rotation_(camera_to_world), fx_(fx), fy_(fy), cx_(cx), cy_(cy), width_(width),
      height_(height) {
  check_size(width, height, "ViewCamera");
  if (!(fx > 0.0 && fy > 0.0 && std::isfinite(fx) && std::isfinite(fy)))
    throw std::invalid_argument("ViewCamera: focal lengths must be positive and finite");
}

Eigen::Vector3d ViewCamera::ray(double x, double y) const {
  const Eigen::Vector3d cam((x - cx_) / fx_, -(y - cy_) / fy_, -1.0);
  return (rotation_ * cam).normalized();
}

std::optional<Eigen::Vector2d> ViewCamera::project(const Eigen::Vector3d& world_dir) const {
  const Eigen::Vector3d cam = rotation_.transpose() * world_dir;
  if (!(cam.z() < 0.0)) return std::nullopt;
  const double depth = -cam.z();
  return Eigen::Vector2d(cx_ + fx_ * cam.x() / depth, cy_ - fy_ * cam.y() / depth);
}

ViewCamera ViewCamera::with_margin(int margin) const {
  if (margin < 0) throw std::invalid_argument("ViewCamera::with_margin: negative margin");
  return ViewCamera(rotation_, fx_, fy_, cx_ + margin, cy_ + margin, width_ + 2 * margin,
                    height_ + 2 * margin);
}

}  // namespace vdfx::effects
