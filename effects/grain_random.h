/// @file
/// @brief Deterministic random numbers for grain: a 64-bit mixing function and a counter-based
/// stream, identical on every platform and compiler (std:: distributions are not).
///
/// mix64 is the finaliser of Steele, Lea and Flood's SplitMix64 (OOPSLA 2014; the constants of
/// Vigna's public-domain splitmix64.c): a bijection of 64-bit words whose output bits each depend
/// on every input bit. A stream is (key, counter) -> mix64(key + counter * golden gamma), which
/// is SplitMix64 itself, so any refresh of any seed can be generated without the ones before.
///
/// hash32 is a 32-bit integer hash for what a GPU must also compute (GLSL has no 64-bit
/// integers, WebGL2 neither): Wellons' "lowbias32" (x ^= x >> 16; x *= 0x7feb352d; x ^= x >> 15;
/// x *= 0x846ca68b; x ^= x >> 16; from his hash-prospector search, 2018, public domain), a
/// bijection with low avalanche bias. Its uniforms are (h >> 8) * 2^-24: 24 bits, exact in a
/// float, so C++ and GLSL start from the same numbers.
#pragma once

#include <cstdint>

namespace vdfx::effects {

/// SplitMix64's output function.
std::uint64_t mix64(std::uint64_t z);

/// Key of one (seed, stream, index) triple, e.g. (effect seed, what is drawn, refresh index).
std::uint64_t random_key(std::uint64_t seed, std::uint64_t stream, std::int64_t index);

/// lowbias32: a bijection of 32-bit words (see above).
constexpr std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

/// Draw j of item i of a counter-based 32-bit stream under `key`: hash32(hash32(key ^ i) ^ j).
/// Any draw of any item is computed alone (no sequence), on the CPU or in a shader.
constexpr std::uint32_t hash32_draw(std::uint32_t key, std::uint32_t i, std::uint32_t j) {
  return hash32(hash32(key ^ i) ^ j);
}

/// A hash as a uniform in [0, 1): (h >> 8) * 2^-24, a multiple of 2^-24 (exact in float).
constexpr double unit_uniform(std::uint32_t h) {
  return static_cast<double>(h >> 8) * 0x1.0p-24;
}

/// A 64-bit key folded to 32 bits (low word xor high word), for hash32_draw.
constexpr std::uint32_t fold32(std::uint64_t k) {
  return static_cast<std::uint32_t>(k ^ (k >> 32));
}

/// A sequential stream of 64-bit words from a key.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t key) : state_(key) {}
  std::uint64_t next();
  /// Uniform in [0, 1): the top 53 bits.
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::uint64_t state_;
};

}  // namespace vdfx::effects
