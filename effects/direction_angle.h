/// @file
/// @brief The angle between two directions in degrees: where the editor compares views and
/// keyframes and the sidecar reader checks a light track's steps.
#pragma once

#include "effects/coords.h"

namespace vdfx::effects {

/// Angle in degrees between two directions: angle_between on their unit vectors (accurate near 0
/// and 180).
double angle_between_deg(const Direction& a, const Direction& b);

}  // namespace vdfx::effects
