/// @file
/// @brief SplitMix64 mixing and streams (constants from Vigna's splitmix64.c, public domain).
#include "effects/grain_random.h"

namespace vdfx::effects {
namespace {
constexpr std::uint64_t kGamma = 0x9e3779b97f4a7c15ull;  // 2^64 / golden ratio, odd
}  // namespace

std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::uint64_t random_key(std::uint64_t seed, std::uint64_t stream, std::int64_t index) {
  // Each component goes through the mixer before the next is added, so (1, 2, 3) and (2, 1, 3)
  // give unrelated keys.
  std::uint64_t k = mix64(seed + kGamma);
  k = mix64(k ^ (stream + kGamma));
  return mix64(k ^ (static_cast<std::uint64_t>(index) + kGamma));
}

std::uint64_t RandomStream::next() {
  state_ += kGamma;
  return mix64(state_);
}

double RandomStream::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

}  // namespace vdfx::effects
