/// @file
/// @brief The UI uses the shared pose type (math/pose.h), not xr/ (which would bring GL and GLFW).
#pragma once

#include "xr/math/pose.h"

namespace vdfx::ui {
using math::Pose;
}  // namespace vdfx::ui
