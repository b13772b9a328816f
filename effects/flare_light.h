/// @file
/// @brief The light direction of a flare at a video frame: fixed, or on a track interpolated
/// along the great circle between its samples (auto lights: effects/auto_light.h).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>

#include "effects/flare.h"

namespace vdfx::effects {

/// Spherical linear interpolation between unit vectors a and b, t in [0, 1]: the point at
/// fraction t of the shorter great-circle arc. Nearly equal vectors fall back to a normalised
/// linear blend; antipodal ones (no unique arc) are the caller's to avoid (the sidecar reader
/// rejects such tracks).
Eigen::Vector3d slerp_unit(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t);

/// Unit direction of a track at `frame`: the samples' great-circle interpolation between the two
/// samples around it, the first sample before the track and the last after it (the contract's
/// "values hold at the nearest end"). `track` is non-empty with strictly increasing frames.
Eigen::Vector3d light_on_track(std::span<const LightSample> track, std::int64_t frame);

}  // namespace vdfx::effects
