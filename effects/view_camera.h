/// @file
/// @brief A pinhole camera looking at a direction of the 360-degree sphere (contract: "Coordinates
/// and time", rendered view).
///
/// Pixel coordinates are continuous: x grows to the right, y grows downwards, the top-left corner
/// of the image is (0, 0) and pixel (i, j) samples through its centre (i + 0.5, j + 0.5).
/// Camera space is OpenXR view space: +x image right, +y image up, -z the optical axis.
/// World rays are unit vectors in OpenXR axes (effects/coords.h).
#pragma once

#include <Eigen/Core>
#include <optional>

#include "effects/coords.h"

namespace vdfx::effects {

/// Field of view of one eye (or view) as tangent extents of its image plane at distance 1, OpenXR
/// sign convention: left and down are normally negative (tan(angleLeft) < 0 < tan(angleRight)).
/// The one FOV description of the project: the camera, the lens model (EyeLens) and the GPU
/// view (xr::RenderView) all use it; OpenXR-style angles convert with FovAngles::tangents().
struct TanRect {
  double left = -1.0;
  double right = 1.0;
  double up = 1.0;
  double down = -1.0;

  /// Normalised image position (u right, v down, both in [0, 1] across the rect) of tangents t.
  Eigen::Vector2d uv_of(const Eigen::Vector2d& t) const {
    return {(t.x() - left) / (right - left), (up - t.y()) / (up - down)};
  }
  /// Tangents at continuous pixel position px of a width x height image spanning the rect.
  Eigen::Vector2d tangent_at(const Eigen::Vector2d& px, int width, int height) const {
    return {left + px.x() / width * (right - left), up - px.y() / height * (up - down)};
  }
  /// Continuous pixel position of tangents t (inverse of tangent_at).
  Eigen::Vector2d pixel_at(const Eigen::Vector2d& t, int width, int height) const {
    const Eigen::Vector2d uv = uv_of(t);
    return {uv.x() * width, uv.y() * height};
  }
};

/// OpenXR-style field of view (XrFovf), in radians: angle_left and angle_down are normally
/// negative, angle_right and angle_up positive. The form headsets and OpenXR report; all geometry
/// works on TanRect, and tangents() is the one conversion between the two.
struct FovAngles {
  double angle_left = -0.785398163397448;
  double angle_right = 0.785398163397448;
  double angle_up = 0.785398163397448;
  double angle_down = -0.785398163397448;
  /// Throws std::invalid_argument unless -pi/2 < left < right < pi/2 and -pi/2 < down < up < pi/2.
  TanRect tangents() const;
};

/// Where the camera looks: the optical axis points at `look`; positive roll turns the image
/// clockwise as the viewer sees it.
struct ViewPose {
  Direction look;
  double roll_deg = 0.0;
};

class ViewCamera {
 public:
  /// Symmetric camera: horizontal field of view in degrees (0, 180), square pixels, optical centre
  /// at the image centre. Throws std::invalid_argument on a bad size or fov.
  static ViewCamera from_horizontal_fov(const ViewPose& pose, double hfov_deg, int width,
                                        int height);
  /// Asymmetric eye camera from OpenXR angles: from_tangents(pose_rotation(pose), fov.tangents()).
  static ViewCamera from_fov_angles(const ViewPose& pose, const FovAngles& fov, int width,
                                    int height);
  /// Asymmetric eye camera: tangent extents spread linearly over width x height pixels, so the
  /// optical centre (tangent 0, 0) may sit off the image centre and the pixels may be non-square.
  /// Throws std::invalid_argument on a bad size or an empty rectangle.
  static ViewCamera from_tangents(const Eigen::Matrix3d& camera_to_world, const TanRect& fov,
                                  int width, int height);
  /// General form: camera-to-world rotation, focal lengths and principal point in pixels.
  ViewCamera(const Eigen::Matrix3d& camera_to_world, double fx, double fy, double cx, double cy,
             int width, int height);

  /// Tangents (x right, y up) of the camera-space ray through continuous pixel coordinates (x, y):
  /// the ray is (tx, ty, -1). The single pixel <-> ray mapping of the project (xr::RenderView
  /// delegates here).
  Eigen::Vector2d tangent(double x, double y) const { return {(x - cx_) / fx_, -(y - cy_) / fy_}; }
  /// Continuous pixel coordinates of camera-space tangents (the inverse of tangent()).
  Eigen::Vector2d pixel_of_tangent(const Eigen::Vector2d& t) const {
    return {cx_ + fx_ * t.x(), cy_ - fy_ * t.y()};
  }
  /// Unit world ray through continuous pixel coordinates (x, y).
  Eigen::Vector3d ray(double x, double y) const;
  /// Unit world ray through the centre of pixel (i, j) = column i, row j.
  Eigen::Vector3d pixel_ray(int i, int j) const { return ray(i + 0.5, j + 0.5); }
  /// Continuous pixel coordinates of a world direction; nullopt when it is not in front of the
  /// camera (on or behind the image plane's parallel through the eye).
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world_dir) const;

  /// The optical axis (unit world vector): the vignette's centre, the view's centre direction.
  Eigen::Vector3d optical_axis() const { return rotation_.col(2) * -1.0; }
  Direction centre_direction() const { return from_unit(optical_axis()); }

  /// The same camera with `margin` extra pixels on every side (same rays for the shared pixels);
  /// used to blur without a border effect.
  ViewCamera with_margin(int margin) const;

  int width() const { return width_; }
  int height() const { return height_; }
  double fx() const { return fx_; }  //!< pixels per radian at the optical centre, horizontally
  double fy() const { return fy_; }  //!< same, vertically
  double cx() const { return cx_; }  //!< principal point, pixels from the left edge
  double cy() const { return cy_; }  //!< principal point, pixels from the top edge
  const Eigen::Matrix3d& camera_to_world() const { return rotation_; }

 private:
  Eigen::Matrix3d rotation_;
  double fx_, fy_, cx_, cy_;
  int width_, height_;
};

/// Camera-to-world rotation of a pose: yaw by -azimuth about +y, pitch by altitude about +x,
/// roll about +z (the optical axis is -z, so +roll turns the camera counter-clockwise and the
/// image content clockwise).
Eigen::Matrix3d pose_rotation(const ViewPose& pose);

}  // namespace vdfx::effects
