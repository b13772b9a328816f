/// @file
/// @brief GLSL sources of the flare layer (strings only: effects/ never links GL). The element
/// profiles are effects/flare_layout.cpp's functions, with the same constants.
#pragma once

#include <string>

namespace vdfx::effects {

/// One flare element as a world-space quad in the flare plane (two triangles, gl_VertexID 0..5,
/// no vertex buffer). Uniforms: u_view_proj (projection x world-to-eye rotation), u_centre (the
/// element's centre minus the eye's position, so floats keep their precision at 100 m), u_axis_u,
/// u_axis_v (unit in-plane axes), u_extent (half-size of the quad, metres), u_support (the same in
/// units of the element's radius). Out: v_q, the in-plane offset from the centre in radii,
/// interpolated perspective-correctly, so at each pixel it is the point where that pixel's ray
/// meets the plane (as the CPU reference computes it).
std::string flare_vertex_source();

/// The element's profile at |v_q| (FlareShape: u_shape 0 glow, 1 ring with u_chroma), times
/// u_colour; output (rgb, 0) for additive blending.
std::string flare_fragment_source();

}  // namespace vdfx::effects
