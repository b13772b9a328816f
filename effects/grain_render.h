/// @file
/// @brief CPU reference of the shader grain styles (headset, surface) for one eye: the layer
/// composited onto an eye image, pixel by pixel, with effects/grain_uniforms.h's uniforms and
/// fragment (the same single-precision arithmetic as the GLSL in effects/grain_shaders.h).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "effects/grain_layout.h"
#include "effects/grain_uniforms.h"
#include "effects/view_camera.h"

namespace vdfx::effects {

/// Composites a shader-style layer onto an upright eye image (CV_32FC3, any channel order).
/// Throws std::invalid_argument for a volumetric layer (those have no CPU reference).
void composite_shader_grain(cv::Mat& image, const GrainFrame& frame,
                            const Eigen::Matrix3d& eye_orientation,
                            const Eigen::Vector3d& eye_position, const TanRect& fov);

}  // namespace vdfx::effects
