/// @file
/// @brief The shader grain styles (headset, surface) for one eye, without OpenCV: the uniforms
/// the GLSL in effects/grain_shaders.h reads and the same single-precision arithmetic per
/// fragment. The CPU reference (effects/grain_render.h) composites it; the web player's module
/// (app/publish/wasm/) hands the uniforms to the page.
///
/// Per pixel: the eye's ray through the pixel centre (tangents of its asymmetric FOV, rotated
/// into the grain frame) meets the grain surface at q:
///  - headset: the plane z = -plane_m of the head frame (origin the head position, axes the
///    head's), t = (-plane_m - e_z) / d_z; noise at (q_x, q_y, 0) / cell;
///  - surface: the sphere |q| = sphere_m around the head position, axes LOCAL's (so it stays put
///    when the head turns), the far root t = -b + sqrt(b^2 - c) of the eye inside it; noise in
///    3-D at q / cell (no seam, no pole pinch).
/// The grain value g = n(q / cell + o1) + w2 n(2 q / cell + o2) (o the refresh's offsets)
/// gives the modulation s = max(-1, intensity * kGrainGain * g), and the eye colour C becomes
/// C' = C + s (C + kGrainFloor) = s kGrainFloor + C (1 + s): grains darken or brighten the
/// image in proportion to its own value, as density grains in film do (hue kept, strongest in
/// the light and mid tones), with a small floor so that shadows keep some grain. The GL layer
/// does the same with dual-source blending (out = src0 + dst src1).
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>

#include "effects/grain_layout.h"
#include "effects/view_camera.h"

namespace vdfx::effects {

/// Everything the shader-style pass reads, in the shader's precision.
struct ShaderGrainUniforms {
  int style = 1;  //!< 0 headset plane, 1 surface sphere
  Eigen::Matrix3f eye_to_grain = Eigen::Matrix3f::Identity();  //!< eye-space ray -> grain frame
  Eigen::Vector3f eye = Eigen::Vector3f::Zero();               //!< eye position in the grain frame
  float distance = 10.0f;  //!< plane distance or sphere radius, metres
  float inv_cell = 1.0f;   //!< 1 / lattice spacing of octave 1, per metre
  Eigen::Vector3f offset1 = Eigen::Vector3f::Zero(), offset2 = Eigen::Vector3f::Zero();
  float octave2 = static_cast<float>(kGrainOctave2Weight);
  float gain = 0.0f;  //!< intensity * kGrainGain
  float floor = static_cast<float>(kGrainFloor);
  std::array<float, 4> tangents{-1, 1, -1, 1};  //!< left, right, down, up
  std::array<int, 256> perm{};                  //!< the permutation of the effect's noise
};

/// The uniforms of one layer for one eye (orientation: eye -> LOCAL; position in LOCAL).
ShaderGrainUniforms shader_grain_uniforms(const GrainFrame& frame,
                                          const Eigen::Matrix3d& eye_orientation,
                                          const Eigen::Vector3d& eye_position, const TanRect& fov);

/// The modulation s at a fragment position in GL's convention (x from the left edge, y from the
/// bottom edge, pixel centres at +0.5) of a width x height eye image; nullopt where the ray
/// misses the grain surface (nothing is drawn there).
std::optional<float> shader_grain_fragment(const ShaderGrainUniforms& u, const PerlinNoise& noise,
                                           float frag_x, float frag_y, int width, int height);

}  // namespace vdfx::effects
