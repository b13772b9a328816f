/// @file
/// @brief What the GPU passes need of one eye's view: orientation, asymmetric tangent FOV and
/// the optical centre. GL-free, so tests and the CPU side share the pixel <-> ray mapping.
///
/// Image convention (contract): pixel (i, j), row j = 0 at the top, samples through its centre
/// (i + 0.5, j + 0.5). The eye looks along -z of its own frame (+x right, +y up, OpenXR), and the
/// pixel's ray in eye space is (tx, ty, -1) with tangents
///   tx = tan_left + (i + 0.5) / W * (tan_right - tan_left),
///   ty = tan_up   - (j + 0.5) / H * (tan_up - tan_down),
/// where tan_left = tan(angleLeft) < 0 and tan_down = tan(angleDown) < 0 as in XrFovf.
/// The mapping itself lives in effects::ViewCamera (camera()): the CPU reference and the GPU
/// passes share one definition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "effects/coords.h"
#include "effects/view_camera.h"

namespace vdfx::xr {

struct RenderView {
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  //!< eye frame -> LOCAL (world)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();         //!< eye position in LOCAL (metres)
  double tan_left = -1.0, tan_right = 1.0, tan_down = -1.0, tan_up = 1.0;
  /// Lens / optical centre in tangent units of this eye (0, 0 = straight ahead of the eye).
  /// The vignette is centred here and the lens distortion is radial about it.
  Eigen::Vector2d optical_centre_tan = Eigen::Vector2d::Zero();

  /// From OpenXR-style angles in radians (left and down negative; effects::FovAngles::tangents(),
  /// which throws std::invalid_argument on an empty or out-of-range FOV).
  static RenderView from_angles(const Eigen::Matrix3d& orientation, double angle_left,
                                double angle_right, double angle_down, double angle_up);

  /// The contract's rendered view: looking at (azimuth, altitude) with roll (positive turns the
  /// image clockwise as the viewer sees it), horizontal FOV in degrees, square pixels.
  static RenderView look_at(const effects::Direction& d, double roll_deg, double hfov_deg,
                            int width, int height);

  effects::TanRect tangents() const { return {tan_left, tan_right, tan_up, tan_down}; }
  /// This view as the CPU reference's camera over width x height pixels (same rays).
  effects::ViewCamera camera(int width, int height) const;

  /// Tangent coordinates of a (fractional) pixel position, e.g. (i + 0.5, j + 0.5).
  Eigen::Vector2d tangent_at(double px, double py, int width, int height) const;
  /// Pixel position (fractional, same convention) of tangent coordinates.
  Eigen::Vector2d pixel_at(const Eigen::Vector2d& tangent, int width, int height) const;
  /// World (LOCAL) unit ray of a pixel position.
  Eigen::Vector3d world_ray(double px, double py, int width, int height) const;

  /// OpenXR-style projection (column-major, GL clip space) of this view's tangent rectangle:
  /// x_ndc = (2 x/(-z) - (tR + tL)) / (tR - tL), likewise y; depth near -> -1, far -> +1, and
  /// far_z <= near_z gives an infinite far plane.
  Eigen::Matrix4d projection(double near_z, double far_z) const;
  /// World (LOCAL) -> eye matrix: the inverse of (orientation, position).
  Eigen::Matrix4d world_to_eye() const;
};

/// Rotation of the contract's view camera: yaw by azimuth, pitch by altitude, roll about forward
/// (effects::pose_rotation).
Eigen::Matrix3d view_rotation(const effects::Direction& d, double roll_deg);

}  // namespace vdfx::xr
