/// @file
/// @brief CPU reference renderer of flares for one view (one eye): each pixel's ray from the
/// eye's own position meets the flare plane, and the elements' profiles are summed there. The GL
/// layer (xr/render/flare_gl.h) draws the same layout as world-space quads and is tested against
/// this.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <span>

#include "effects/flare_layout.h"
#include "effects/view_camera.h"

namespace vdfx::effects {

/// The light a flare adds at one world ray from `eye` (RGB, 0 when the ray misses the plane).
Eigen::Vector3d flare_at_ray(const FlareLayout& layout, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& ray);

/// Adds every layout's light to `rgb` (CV_32FC3, the camera's size), seen from `eye` (world
/// position, metres) through `camera` (its rotation and FOV; pixel centres at +0.5). Additive and
/// unclamped, like the effect stack's output it goes on.
void add_flares(cv::Mat& rgb, const ViewCamera& camera, const Eigen::Vector3d& eye,
                std::span<const FlareLayout> layouts);

}  // namespace vdfx::effects
