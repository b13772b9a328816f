/// @file
/// @brief Deterministic random numbers for grain: a 64-bit mixing function and a counter-based
/// stream, identical on every platform and compiler (std:: distributions are not).
///
/// mix64 is the finaliser of Steele, Lea and Flood's SplitMix64 (OOPSLA 2014; the constants of
/// Vigna's public-domain splitmix64.c): a bijection of 64-bit words whose output bits each depend
/// on every input bit. A stream is (key, counter) -> mix64(key + counter * golden gamma), which
/// is SplitMix64 itself, so any refresh of any seed can be generated without the ones before.
#pragma once

#include <cstdint>

namespace vdfx::effects {

/// SplitMix64's output function.
std::uint64_t mix64(std::uint64_t z);

/// Key of one (seed, stream, index) triple, e.g. (effect seed, what is drawn, refresh index).
std::uint64_t random_key(std::uint64_t seed, std::uint64_t stream, std::int64_t index);

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
