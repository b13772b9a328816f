/// @file
/// @brief Improved gradient noise (Perlin, "Improving Noise", SIGGRAPH 2002) in 3-D: the C++
/// reference of the GLSL noise in effects/grain_shaders.h.
///
/// The 2002 method: integer lattice, a permutation of 0..255 hashes each lattice corner
/// (hash(i) = P[i mod 256], corner (X, Y, Z) -> P[P[P[X] + Y] + Z]), the corner's gradient is one
/// of the 12 directions from a cube's centre to its edge midpoints (a 16-entry table with four of
/// them repeated, so a hash picks one with `& 15`), each corner contributes dot(gradient, offset),
/// and the eight contributions are blended with the quintic fade 6t^5 - 15t^4 + 10t^3 (continuous
/// second derivative). The noise is 0 at lattice points and within about [-1, 1].
/// Perlin's own table is one fixed permutation; here the permutation is drawn from a seed
/// (Fisher-Yates on effects::RandomStream) so that two grain effects differ.
///
/// Evaluated in single precision, in the operation order the GLSL uses, so the two agree to float
/// rounding (tests/xr/render/grain_gl_test.cpp).
#pragma once

#include <array>
#include <cstdint>

namespace vdfx::effects {

class PerlinNoise {
 public:
  /// The permutation drawn from `seed`.
  explicit PerlinNoise(std::uint64_t seed);

  /// Noise at (x, y, z); period 256 in each axis.
  float operator()(float x, float y, float z) const;

  /// The permutation P (P[i] in 0..255, each value once), as the shader receives it.
  const std::array<std::uint8_t, 256>& permutation() const { return perm_; }

  /// The 16 gradient directions of the 2002 paper (components -1, 0, 1).
  static const std::array<std::array<float, 3>, 16>& gradients();

 private:
  int hash(int i) const { return perm_[static_cast<std::size_t>(i & 255)]; }
  std::array<std::uint8_t, 256> perm_{};
};

/// The quintic fade 6t^5 - 15t^4 + 10t^3, in the shader's operation order.
inline float perlin_fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

}  // namespace vdfx::effects
