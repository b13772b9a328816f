/// @file
/// @brief StackInterpolator: per-effect RBFs, inactive effects skipped, anchored effects at the
/// turned direction.
#include "effects/stack_interpolator.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace vdfx::effects {

StackInterpolator::StackInterpolator(const std::vector<EffectTrack>& tracks,
                                     const InterpolationSettings& defaults, double fps,
                                     const AnchorSources& anchors) {
  std::array<bool, kEffectCount> seen{};
  AnchorResolver resolve(anchors);
  for (const EffectTrack& t : tracks) {
    auto& slot = solutions_[index(t.type)];
    if (std::exchange(seen[index(t.type)], true))
      throw std::invalid_argument("StackInterpolator: two tracks for effect " +
                                  std::string(effect_name(t.type)));
    if (t.keyframes.empty()) continue;
    anchors_[index(t.type)] = resolve.resolve(t.anchor);
    const EffectSpec& spec = effect_spec(t.type);
    slot = std::make_shared<const RbfInterpolator>(
        t.keyframes, spec.dimension(), t.interpolation.value_or(defaults), fps, spec.neutral());
  }
  link_anchors();
}

StackInterpolator::StackInterpolator(Solutions solutions, Anchors anchors)
    : solutions_(std::move(solutions)), anchors_(std::move(anchors)) {
  for (auto& s : solutions_)
    if (s && s->empty()) s.reset();
  link_anchors();
}

void StackInterpolator::link_anchors() {
  const Anchor* last = nullptr;
  for (std::size_t e = 0; e < solutions_.size(); ++e) {
    if (!solutions_[e] || anchors_[e].frames.identity()) continue;
    reuse_[e] = last && *last == anchors_[e].anchor;
    last = &anchors_[e].anchor;
  }
}

StackParams StackInterpolator::evaluate(const Direction& direction, std::int64_t frame) const {
  return evaluate(to_unit(direction), frame);
}

StackParams StackInterpolator::evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const {
  StackParams p;
  double values[3];
  Eigen::Vector3d turned;  // the direction in the anchor's frame of the last anchored effect
  for (int e = 0; e < kEffectCount; ++e) {
    const auto i = static_cast<std::size_t>(e);
    const auto& s = solutions_[i];
    if (!s) continue;
    const AnchorFrames& a = anchors_[i].frames;
    if (a.identity()) {
      s->evaluate_into(unit, frame, values);
    } else {
      if (!reuse_[i]) turned = a.apply(unit, frame);
      s->evaluate_into(turned, frame, values);
    }
    p.set(static_cast<EffectType>(e),
          std::span<const double>(values, static_cast<std::size_t>(s->dimension())));
  }
  return p;
}

namespace {
StackInterpolator::Solutions turned_solutions(const StackInterpolator& stack, std::int64_t frame) {
  StackInterpolator::Solutions out;
  for (int e = 0; e < kEffectCount; ++e) {
    const auto type = static_cast<EffectType>(e);
    const RbfInterpolator* s = stack.interpolator(type);
    if (!s) continue;
    const AnchorFrames& a = stack.anchor(type);
    // The RBF sees a.apply(u, frame) = R u: its centres turn by R instead, once.
    out[static_cast<std::size_t>(e)] =
        a.identity() ? stack.solution(type) : s->turned_for_frame(a.at(frame), frame);
  }
  return out;
}
}  // namespace

StackAtFrame::StackAtFrame(const StackInterpolator& stack, std::int64_t frame)
    : turned_(turned_solutions(stack, frame)), frame_(frame) {}

}  // namespace vdfx::effects
