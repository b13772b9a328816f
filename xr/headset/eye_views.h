/// @file
/// @brief Per-eye views of the simulated headset (OpenXR's xrLocateViews): eye poses, asymmetric
/// FOV, projection and view matrices, the optical centre in each eye's image, and a Direction-
/// based camera description for the CPU reference renderer.
///
/// Axes are OpenXR's (+x right, +y up, -z forward), poses are in the LOCAL reference space, and
/// matrices are column-major GLM (double; cast with glm::mat4(m) for GL uniforms).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "effects/coords.h"
#include "xr/headset/hmd_profile.h"
#include "xr/headset/pose.h"

namespace vdfx::xr {

/// Clip-space depth convention of the projection matrix.
enum class ClipDepth { MinusOneToOne /* OpenGL */, ZeroToOne /* Vulkan, D3D */ };

/// OpenXR-style projection from the four FOV tangents (derivation in docs/hmd-profiles.md):
/// x_ndc = (2 x/(-z) - (tR + tL)) / (tR - tL), likewise y; depth maps near -> -1 (or 0) and
/// far -> +1. far <= near gives an infinite far plane, as XrMatrix4x4f_CreateProjectionFov does.
glm::dmat4 projection_from_fov(const FovDeg& fov, double near_z, double far_z,
                               ClipDepth depth = ClipDepth::MinusOneToOne);

/// World-to-eye matrix of a pose (the inverse of its rigid transform).
glm::dmat4 view_from_pose(const Pose& pose);

struct EyeView {
  Eye eye = Eye::Left;
  Pose pose;             //!< the eye in LOCAL space: head pose offset by -+IPD/2 along head x
  FovDeg fov;            //!< asymmetric FOV, degrees
  glm::dmat4 view{1.0};  //!< world -> eye
  glm::dmat4 projection{1.0};
  int width = 0, height = 0;  //!< the eye's image / panel viewport, pixels
};

/// Both eyes (left, right) for a head pose, as xrLocateViews returns them.
std::array<EyeView, 2> locate_eye_views(const Pose& head, const HmdProfile& profile,
                                        double near_z = 0.05, double far_z = 100.0);

/// Continuous pixel position (x right, y down, pixel centres at +0.5) of a world point in an eye's
/// image; nullopt-free: a point behind the eye returns NaN.
glm::dvec2 project_to_pixel(const EyeView& view, const glm::dvec3& world_point);

/// Where "straight ahead" lands in an eye's image: the point 10 units along head forward,
/// projected through that eye's view-projection. Differs from the image centre for asymmetric
/// FOVs, and by the eye's IPD offset from the FOV's optical centre (parallax at 10 units).
glm::dvec2 optical_centre_px(const EyeView& view, const Pose& head);

/// One eye's camera for the CPU reference (effects/view_camera: ViewCamera::from_fov_angles):
/// where the eye looks, its roll, and its FOV in radians. Eye translation is dropped: the video
/// is a sphere at infinity.
struct EyeCamera {
  effects::Direction look;  //!< head forward (both eyes look the same way)
  double roll_deg = 0.0;    //!< positive turns the image clockwise as the viewer sees it
  double angle_left = 0.0;  //!< radians, OpenXR signs (XrFovf)
  double angle_right = 0.0;
  double angle_up = 0.0;
  double angle_down = 0.0;
  int width = 0, height = 0;
};

EyeCamera eye_camera(const Pose& head, const HmdProfile& profile, Eye eye);

/// Camera-to-world rotation of (look, roll): yaw by -azimuth about +y, pitch by altitude about
/// +x, roll about +z; the columns are the camera's right, up and back axes.
glm::dmat3 camera_rotation(const effects::Direction& look, double roll_deg);

}  // namespace vdfx::xr
