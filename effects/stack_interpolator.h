/// @file
/// @brief Interpolates the whole effect stack at one view: one RBF per effect with keyframes.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "effects/effect_types.h"
#include "effects/keyframe.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::effects {

class StackInterpolator {
 public:
  using Solutions = std::array<std::shared_ptr<const RbfInterpolator>, kEffectCount>;

  /// One track per EffectType at most (throws std::invalid_argument naming the duplicate); a
  /// track's own interpolation settings override `defaults`.
  StackInterpolator(const std::vector<EffectTrack>& tracks, const InterpolationSettings& defaults,
                    double fps);
  /// From already solved interpolators (e.g. KeyframeSet::solution()), indexed by EffectType;
  /// null or empty ones are inactive.
  explicit StackInterpolator(Solutions solutions);

  /// Effects without keyframes are not evaluated and stay neutral; values are clamped to the
  /// contract's ranges and tint renormalised (StackParams::set).
  StackParams evaluate(const Direction& direction, std::int64_t frame) const;
  StackParams evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const;

  bool active(EffectType type) const { return solutions_[index(type)] != nullptr; }
  const RbfInterpolator* interpolator(EffectType type) const {
    return solutions_[index(type)].get();
  }

 private:
  static std::size_t index(EffectType t) { return static_cast<std::size_t>(t); }
  Solutions solutions_;
};

}  // namespace vdfx::effects
