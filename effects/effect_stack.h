/// @file
/// @brief CPU reference of the effect stack (contract: "Effects, their parameters and neutral
/// values"), in the paper's order: blur, tint, exposure, saturation, contrast, vignette.
///
/// Colours are RGB (not OpenCV's BGR) in the video's encoded values, nominally [0, 1], with no
/// linearisation; images are CV_32FC3. Every formula is computed in double per pixel, each effect
/// on the output of the one before, with no clamping in between: clamp_output() (or to_rgb8() of
/// the view renderer) clamps once at the very end. An effect at its neutral value is skipped
/// (StackParams::is_neutral), so it is exactly the identity.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "effects/effect_types.h"
#include "effects/view_camera.h"

namespace vdfx::effects {

// ---- Per pixel (the GL path is compared against these) ------------------------------------------

/// C * gain (gain already normalised: StackParams holds it normalised).
Eigen::Vector3d apply_tint(const Eigen::Vector3d& c, const Eigen::Vector3d& gain);
/// C * 2^stops.
Eigen::Vector3d apply_exposure(const Eigen::Vector3d& c, double stops);
/// Y + S (C - Y), Y = C . [0.25, 0.5, 0.25].
Eigen::Vector3d apply_saturation(const Eigen::Vector3d& c, double amount);
/// 0.5 + X (C - 0.5).
Eigen::Vector3d apply_contrast(const Eigen::Vector3d& c, double amount);
/// f = 1 (d <= R), 1 - (d - R) / F (d <= R + F), 0 beyond; all in degrees. F <= 0 is a hard edge.
double vignette_factor(double d_deg, double radius_deg, double falloff_deg);
/// C f + (1 - f) black, black = 0.
Eigen::Vector3d apply_vignette(const Eigen::Vector3d& c, double d_deg, double radius_deg,
                               double falloff_deg);

/// Tint, exposure, saturation, contrast, vignette (the stack after blur) for one pixel whose ray
/// makes `vignette_angle_deg` with the optical axis; neutral effects skipped; not clamped.
Eigen::Vector3d apply_colour_stack(const Eigen::Vector3d& c, const StackParams& p,
                                   double vignette_angle_deg);

/// Clamps each channel to [0, 1] (the output step, never between effects).
Eigen::Vector3d clamp_output(const Eigen::Vector3d& c);

// ---- Whole image --------------------------------------------------------------------------------

/// Angle in degrees between each pixel's ray and the optical axis (CV_64FC1, camera size).
cv::Mat vignette_angle_map(const ViewCamera& camera);

/// Blur sigmas in pixels of a sigma in degrees for this camera: (fx, fy) * sigma in radians
/// (see sigma_px_from_deg in gaussian_blur.h).
Eigen::Vector2d blur_sigma_px(const ViewCamera& camera, double sigma_deg);

/// The colour part of the stack on a whole CV_32FC3 image; `angle_deg` from vignette_angle_map.
cv::Mat apply_colour_stack(const cv::Mat& rgb, const StackParams& p, const cv::Mat& angle_deg);

/// The whole stack on an image seen through `camera` (same size): separable blur (edge pixels
/// repeated at the border), then the colour stack. Unclamped CV_32FC3.
cv::Mat apply_stack(const cv::Mat& rgb, const StackParams& p, const ViewCamera& camera);

}  // namespace vdfx::effects
