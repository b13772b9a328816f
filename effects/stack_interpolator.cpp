/// @file
/// @brief StackInterpolator: per-effect RBFs, inactive effects skipped.
#include "effects/stack_interpolator.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace vdfx::effects {

StackInterpolator::StackInterpolator(const std::vector<EffectTrack>& tracks,
                                     const InterpolationSettings& defaults, double fps) {
  std::array<bool, kEffectCount> seen{};
  for (const EffectTrack& t : tracks) {
    auto& slot = solutions_[index(t.type)];
    if (std::exchange(seen[index(t.type)], true))
      throw std::invalid_argument("StackInterpolator: two tracks for effect " +
                                  std::string(effect_name(t.type)));
    if (t.keyframes.empty()) continue;
    const EffectSpec& spec = effect_spec(t.type);
    slot = std::make_shared<const RbfInterpolator>(
        t.keyframes, spec.dimension(), t.interpolation.value_or(defaults), fps, spec.neutral());
  }
}

StackInterpolator::StackInterpolator(Solutions solutions) : solutions_(std::move(solutions)) {
  for (auto& s : solutions_)
    if (s && s->empty()) s.reset();
}

StackParams StackInterpolator::evaluate(const Direction& direction, std::int64_t frame) const {
  return evaluate(to_unit(direction), frame);
}

StackParams StackInterpolator::evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const {
  StackParams p;
  double values[3];
  for (int e = 0; e < kEffectCount; ++e) {
    const auto& s = solutions_[static_cast<std::size_t>(e)];
    if (!s) continue;
    s->evaluate_into(unit, frame, values);
    p.set(static_cast<EffectType>(e),
          std::span<const double>(values, static_cast<std::size_t>(s->dimension())));
  }
  return p;
}

}  // namespace vdfx::effects
