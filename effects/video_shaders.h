/// @file
/// @brief GLSL of the video layer (strings only: effects/ never links GL): each pixel's ray
/// into the equirect frame, shared by the GL compositor (xr/render/video_layer.cpp) and the page of
/// `vdfx publish`. The level-of-detail formulas are documented in xr/render/video_layer.h.
#pragma once

#include <string>

namespace vdfx::effects {

/// The video layer's fragment shader (after glsl_common.h's constants, pinhole and equirect
/// mapping). Uniforms: u_equirect (an RGB frame, t = 1 - v, its mip chain built by
/// mip_level_fragment_source()), u_rot (eye -> world), u_lod_mode (3 the footprint filter of
/// effects/pixel_footprint.h with u_max_aniso, the definition; 0 textureGrad with analytic
/// gradients, 1 hardware derivatives, 2 level 0 only: GL's isotropic mipmapping, kept as peers),
/// u_tan, u_size; with u_ycbcr = 1 the frame is three planes converted per sample (u_plane0..2,
/// u_chroma_scale, u_chroma_offset, u_chroma_lod, u_code_scale, u_m, u_offset: io/ycbcr.h).
std::string video_layer_fragment_source();

/// One level of the area-average mip chain (effects/mip_chain.h) from the level above: drawn over
/// the new level's viewport with u_src's base (and max) level set to the level above. Any
/// colour format: each channel is averaged alike.
std::string mip_level_fragment_source();

}  // namespace vdfx::effects
