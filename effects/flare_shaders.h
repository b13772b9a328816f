/// @file
/// @brief GLSL sources of the flare layer (strings only: effects/ never links GL). The element
/// profiles are effects/flare_layout.cpp's functions, with the same constants.
#pragma once

#include <string>

namespace vdfx::effects {

/// One flare element as a world-space quad in the flare plane (two triangles, gl_VertexID 0..5,
/// no vertex buffer): the pixels it may light. Uniforms: u_view_proj (projection x world-to-eye
/// rotation), u_centre (the element's centre minus the eye's position, so floats keep their
/// precision at 100 m), u_axis_u, u_axis_v (unit in-plane axes), u_extent (half-size of the quad,
/// metres).
std::string flare_vertex_source();

/// The element's profile (FlareShape: u_shape 0 glow, 1 ring with u_chroma) times u_colour,
/// output (rgb, 0) for additive blending, at the point where the fragment's own ray (the pinhole:
/// u_tan, u_size; u_eye_rot, eye -> world) meets the element's plane, in radii (u_support /
/// u_extent per metre) from its centre: the CPU reference's arithmetic, not a varying
/// interpolated from the quad's corners.
std::string flare_fragment_source();

}  // namespace vdfx::effects
