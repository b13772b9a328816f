/// @file
/// @brief PerlinNoise: seeded permutation, corner hashing, gradient dot products, quintic blend.
#include "effects/perlin_noise.h"

#include <cmath>
#include <numeric>

#include "effects/grain_random.h"

namespace vdfx::effects {
namespace {

constexpr std::uint64_t kPermutationStream = 0x7065726d;  // "perm"

float lerp(float t, float a, float b) {
  return a + t * (b - a);
}

}  // namespace

const std::array<std::array<float, 3>, 16>& PerlinNoise::gradients() {
  // The twelve edge midpoints of the cube [-1, 1]^3, then (1,1,0), (0,-1,1), (-1,1,0), (0,-1,-1)
  // again, in the order the paper's hash-bit selection gives entries 12..15. Four hash bits pick
  // an entry without a division (the paper's choice; the repeats make those four directions
  // slightly more frequent, which it found invisible).
  // clang-format off
  static const std::array<std::array<float, 3>, 16> g = {{
      {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
      {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
      {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1},
      {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1},
  }};
  // clang-format on
  return g;
}

PerlinNoise::PerlinNoise(std::uint64_t seed) {
  std::iota(perm_.begin(), perm_.end(), std::uint8_t{0});
  RandomStream rng(random_key(seed, kPermutationStream, 0));
  for (std::size_t i = perm_.size() - 1; i > 0; --i) {
    const std::size_t j = static_cast<std::size_t>(rng.next() % (i + 1));
    std::swap(perm_[i], perm_[j]);
  }
}

float PerlinNoise::operator()(float x, float y, float z) const {
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int X = static_cast<int>(fx) & 255, Y = static_cast<int>(fy) & 255,
            Z = static_cast<int>(fz) & 255;
  const float dx = x - fx, dy = y - fy, dz = z - fz;
  const float u = perlin_fade(dx), v = perlin_fade(dy), w = perlin_fade(dz);
  // Corner hashes, as P[P[P[X] + Y] + Z] with the sums taken mod 256.
  const int a = hash(X) + Y, b = hash(X + 1) + Y;
  const int aa = hash(a) + Z, ab = hash(a + 1) + Z, ba = hash(b) + Z, bb = hash(b + 1) + Z;
  const auto& g = gradients();
  // Each gradient has exactly two non-zero components of +-1, so the dot product is one rounded
  // addition whatever order the shader compiler picks.
  const auto corner = [&](int h, float ox, float oy, float oz) {
    const auto& d = g[static_cast<std::size_t>(h & 15)];
    return d[0] * ox + d[1] * oy + d[2] * oz;
  };
  const float x1 = dx - 1.0f, y1 = dy - 1.0f, z1 = dz - 1.0f;
  const float n000 = corner(hash(aa), dx, dy, dz), n100 = corner(hash(ba), x1, dy, dz);
  const float n010 = corner(hash(ab), dx, y1, dz), n110 = corner(hash(bb), x1, y1, dz);
  const float n001 = corner(hash(aa + 1), dx, dy, z1), n101 = corner(hash(ba + 1), x1, dy, z1);
  const float n011 = corner(hash(ab + 1), dx, y1, z1), n111 = corner(hash(bb + 1), x1, y1, z1);
  const float near = lerp(v, lerp(u, n000, n100), lerp(u, n010, n110));
  const float far = lerp(v, lerp(u, n001, n101), lerp(u, n011, n111));
  return lerp(w, near, far);
}

}  // namespace vdfx::effects
