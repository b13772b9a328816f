/// @file
/// @brief GLSL of the video layer (strings only: effects/ never links GL): each pixel's ray
/// into the equirect frame, shared by the GL compositor (xr/render/video_layer.cpp) and the page of
/// `vdfx publish`. The level-of-detail formulas are documented in xr/render/video_layer.h.
#pragma once

#include <string>

namespace vdfx::effects {

/// The video layer's fragment shader (after glsl_common.h's constants, pinhole and equirect
/// mapping). Uniforms: u_equirect (an RGB frame, t = 1 - v), u_rot (eye -> world), u_lod_mode
/// (0 analytic gradients, 1 hardware derivatives, 2 level 0 only), u_tan, u_size; with u_ycbcr = 1
/// the frame is three planes converted per sample (u_plane0..2, u_chroma_scale, u_chroma_offset,
/// u_code_scale, u_m, u_offset: io/ycbcr.h).
std::string video_layer_fragment_source();

}  // namespace vdfx::effects
