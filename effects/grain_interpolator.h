/// @file
/// @brief The keyframed parameters of one grain effect (intensity, size) over direction and
/// frame: the project's RBF (effects/rbf_interpolator.h), as for every other effect.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "effects/grain.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::effects {

class GrainInterpolator {
 public:
  /// Solves the effect's keyframes (its own interpolation settings override `defaults`).
  /// Throws std::invalid_argument as RbfInterpolator does.
  GrainInterpolator(const GrainEffect& effect, const InterpolationSettings& defaults, double fps);
  /// Another solution of the keyframes (an editor's pending edit); dimension 2.
  explicit GrainInterpolator(std::shared_ptr<const RbfInterpolator> rbf);

  /// Intensity clamped to [0, 1], size to [0.25, 4] (interpolation may overshoot). Without
  /// keyframes: intensity 0 (the neutral value: nothing is drawn).
  GrainParams evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const;
  GrainParams evaluate(const Direction& direction, std::int64_t frame) const;
  bool active() const { return !rbf_->empty(); }

 private:
  std::shared_ptr<const RbfInterpolator> rbf_;
};

}  // namespace vdfx::effects
