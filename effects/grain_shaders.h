/// @file
/// @brief GLSL sources of the grain layer (strings only: effects/ never links GL). The C++
/// reference of the shader styles is effects/grain_render.h (same uniforms, same operations);
/// the noise is effects/perlin_noise.h's.
#pragma once

#include <string>

namespace vdfx::effects {

/// Full-screen pass of the shader styles (headset, surface). Uniforms: u_perm (ivec4[64], the
/// permutation packed four per element), u_style, u_eye_to_grain, u_eye, u_distance, u_inv_cell,
/// u_offset1, u_offset2, u_octave2, u_gain, u_floor, u_tan (left, right, down, up), u_viewport
/// (W, H). Desktop GL: two outputs for dual-source blending (ONE, SRC1_COLOR): frag = s floor,
/// frag_scale = 1 + s, so the eye colour C becomes s floor + C (1 + s). GLSL ES (WebGL2, no
/// dual-source blending): one output (s floor, 1 + s) for blending (ONE, SRC_ALPHA) into a float
/// target, the same result.
std::string grain_shader_fragment_source();

/// Instanced particles (object_cloud, free_cloud): one camera-facing quad per particle (a
/// 4-vertex triangle strip, gl_VertexID 0..3) that bounds its ellipsoid. No attributes: the
/// particle of gl_InstanceID is generated in the vertex stage as effects::grain_particle defines
/// it, from u_key (grain_particle_key), u_cloud (0 object_cloud, 1 free_cloud),
/// u_shell_threshold, u_radii (shell r0, ln(r1 / r0), surrounding r0, ln(r1 / r0)), u_cylinder
/// (radius, height), u_extent_range (min, max - min) and u_min_opacity. Drawing uniforms:
/// u_view_proj (grain frame -> clip), u_eye (eye in the grain frame), u_eye_up, u_eye_right,
/// u_size, u_intensity, u_px_per_tan.
std::string grain_particle_vertex_source();

/// The particle's fragment: the eye's ray through the fragment against the ellipsoid; weight the
/// squared chord through it, normalised (1 through the centre, falling as 1 - r^2 to 0 at the
/// rim: a soft grain, not a disc). The particle modulates the eye colour as the shader styles do
/// (s = (2 brightness - 1) opacity intensity weight, C -> s floor + C (1 + s), dual-source
/// blending; uniform u_floor): a dark grain darkens, a bright one brightens, and the hue stays.
std::string grain_particle_fragment_source();

/// Near fade of particles (metres from the eye): none beyond the end, all below the start.
inline constexpr double kParticleNearFadeStartM = 0.1;
inline constexpr double kParticleNearFadeEndM = 0.3;
/// Angular radius beyond which a particle (one near the eye) fades as (this / radius)^2, keeping
/// the coverage of a grain this size: volumetric grain stays grain-sized instead of showing the
/// nearest particles as flakes. 2 mrad is about 1.2 px of a 1440-px, 100-degree eye.
inline constexpr double kParticleMaxRadiusRad = 0.002;
/// Smallest drawn semi-axis in pixels: a smaller one is drawn this large with the opacity scaled
/// by the volume ratio to the 2/3 (about the same coverage). Whole-pixel footprints keep a grain
/// from flickering as it moves and make both eyes sample it alike (the stereo test's correlation
/// of an object cloud: 0.79 at 0.75 px on the largest axis only, 0.93 at 1 px on every axis).
inline constexpr double kParticleMinRadiusPx = 1.0;

}  // namespace vdfx::effects
