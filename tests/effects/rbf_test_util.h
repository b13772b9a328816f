/// @file
/// @brief Shared helpers of the RBF tests: random keyframes and independent expectations.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "effects/coords.h"
#include "effects/keyframe.h"

namespace vdfx::effects::test {

inline Direction random_direction(std::mt19937_64& rng) {
  // Uniform on the sphere (altitude from asin of a uniform height).
  std::uniform_real_distribution<double> u(-1.0, 1.0), az(-180.0, 180.0);
  return {az(rng), std::asin(u(rng)) * kRadToDeg};
}

inline Keyframe random_keyframe(std::mt19937_64& rng, int dimension, std::int64_t frame_lo,
                                std::int64_t frame_hi) {
  std::uniform_int_distribution<std::int64_t> f(frame_lo, frame_hi);
  std::uniform_real_distribution<double> v(0.0, 4.0);
  Keyframe k;
  k.direction = random_direction(rng);
  k.frame = f(rng);
  for (int i = 0; i < dimension; ++i) k.params.push_back(v(rng));
  return k;
}

/// Mean of the params of every keyframe coincident with keyframes[i] (same frame, chord below
/// 1e-11): what the interpolant must reproduce there.
inline Eigen::VectorXd expected_value(const std::vector<Keyframe>& keyframes, size_t i) {
  const Eigen::Vector3d ui = to_unit(keyframes[i].direction);
  Eigen::VectorXd sum =
      Eigen::VectorXd::Zero(static_cast<Eigen::Index>(keyframes[i].params.size()));
  int n = 0;
  for (const Keyframe& k : keyframes) {
    if (k.frame != keyframes[i].frame || (to_unit(k.direction) - ui).norm() > 1e-11) continue;
    sum += Eigen::Map<const Eigen::VectorXd>(k.params.data(), sum.size());
    ++n;
  }
  return sum / n;
}

}  // namespace vdfx::effects::test
