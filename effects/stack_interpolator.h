/// @file
/// @brief Interpolates the whole effect stack at one view: one RBF per effect with keyframes,
/// each at the view direction turned into its anchor's frame (effects/anchor.h).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "effects/anchor_sources.h"
#include "effects/effect_types.h"
#include "effects/keyframe.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::effects {

class StackInterpolator {
 public:
  using Solutions = std::array<std::shared_ptr<const RbfInterpolator>, kEffectCount>;
  /// Each effect's anchor, indexed by EffectType (default: the video anchor, the identity).
  using Anchors = std::array<ResolvedAnchor, kEffectCount>;

  /// One track per EffectType at most (throws std::invalid_argument naming the duplicate); a
  /// track's own interpolation settings override `defaults`. Each track's anchor is resolved
  /// against `anchors` (throws std::invalid_argument when it names what they lack).
  StackInterpolator(const std::vector<EffectTrack>& tracks, const InterpolationSettings& defaults,
                    double fps, const AnchorSources& anchors = {});
  /// From already solved interpolators (e.g. KeyframeSet::solution()), indexed by EffectType;
  /// null or empty ones are inactive.
  explicit StackInterpolator(Solutions solutions, Anchors anchors = {});

  /// Effects without keyframes are not evaluated and stay neutral; values are clamped to the
  /// contract's ranges and tint renormalised (StackParams::set). The direction is one of the
  /// video frame at `frame`; an anchored effect's RBF sees it turned into its anchor's frame.
  StackParams evaluate(const Direction& direction, std::int64_t frame) const;
  StackParams evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const;

  bool active(EffectType type) const { return solutions_[index(type)] != nullptr; }
  const RbfInterpolator* interpolator(EffectType type) const {
    return solutions_[index(type)].get();
  }
  const std::shared_ptr<const RbfInterpolator>& solution(EffectType type) const {
    return solutions_[index(type)];
  }
  const AnchorFrames& anchor(EffectType type) const { return anchors_[index(type)].frames; }

 private:
  static std::size_t index(EffectType t) { return static_cast<std::size_t>(t); }
  /// reuse_ from the anchors of the active effects.
  void link_anchors();
  Solutions solutions_;
  Anchors anchors_;
  /// Per effect: it has the anchor of the last anchored active effect before it, so the
  /// direction turned for that one serves it too.
  std::array<bool, kEffectCount> reuse_{};
};

/// The stack at one frame, for many directions (the per-pixel grid: 32,768 evaluations of one
/// frame): each anchored effect's centres are turned into the video frame at that frame once, so
/// each evaluation costs what an unanchored one does (docs/anchors.md, "Measured: anchor cost").
/// evaluate(d) is stack.evaluate(d, frame) to rounding. Immutable: share it between threads.
class StackAtFrame {
 public:
  StackAtFrame(const StackInterpolator& stack, std::int64_t frame);
  StackParams evaluate(const Direction& direction) const {
    return turned_.evaluate(direction, frame_);
  }
  StackParams evaluate(const Eigen::Vector3d& unit) const { return turned_.evaluate(unit, frame_); }
  std::int64_t frame() const { return frame_; }

 private:
  StackInterpolator turned_;  //!< no anchors: the anchored effects' solutions turned
  std::int64_t frame_;
};

}  // namespace vdfx::effects
