/// @file
/// @brief The UI uses the runtime's pose type (xr/pose.h).
#pragma once

#include "xr/pose.h"

namespace vdfx::ui {
using Pose = xr::Pose;
}  // namespace vdfx::ui
