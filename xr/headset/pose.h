/// @file
/// @brief The runtime's pose type and pose helpers: math/pose.h, named in xr/.
#pragma once

#include "xr/math/pose.h"

namespace vdfx::xr {
using math::forward;
using math::forward_direction;
using math::look_rotation;
using math::Pose;
}  // namespace vdfx::xr
