/// @file
/// @brief The live preview's interpolant: one effect's keyframes with one keyframe (a new one
/// being placed, or a grabbed one being moved) at a place that changes every frame.
///
/// A fresh RbfInterpolator per frame is an O(N^3) solve (tens of ms at N = 1000). Instead a
/// scratch effects::KeyframeSet is seeded once when the preview starts, and each later frame
/// applies one O(N^2) KeyframeSet::move (and set_params when the values change) to the preview
/// keyframe. The seed clones the document's solved set (KeyframeSet::clone: a copy of its exact
/// incremental state, O(N^2), no solve) and applies one incremental add or move of the preview
/// keyframe; only without a source set, or when the source has no exact state (merged keyframes,
/// an asynchronous re-solve still running), does it run one full O(N^3) solve. The result equals a fresh solve of the same keyframes
/// (tested to 1e-9). Keyframes the preview keyframe lands on (within effects::kReplaceAngleDeg
/// at its frame, the rule the edit will apply) are left out of the interpolant while it sits
/// there and come back when it moves off: the set is re-seeded whenever that list, the
/// document's keyframes or the settings change (rare during a preview).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "effects/keyframe_set.h"

namespace vdfx::app {

/// What the preview interpolates: the document's keyframes of one effect, and the preview
/// keyframe, which is a new keyframe (moved = nullopt) or keyframe `*moved` moved to `key`.
struct PreviewTarget {
  const std::vector<effects::Keyframe>* keyframes = nullptr;  //!< the document's, not owned
  std::uint64_t revision = 0;  //!< grows when *keyframes may have changed (Document::revision)
  std::optional<std::size_t> moved;
  effects::Keyframe key;  //!< where the preview keyframe is now, with its values
  int effect = 0;         //!< identity only: another effect re-seeds
  int dimension = 1;
  std::vector<double> neutral;
  effects::InterpolationSettings settings;
  double fps = 30.0;
  //! The document's solved set of exactly *keyframes with these settings, fps, dimension and
  //! neutral values (Document::keyframe_set), not owned; seeds clone it. Null: seeds solve.
  const effects::KeyframeSet* source = nullptr;
};

/// The keyframes a preview interpolant uses: `keyframes` without the ones the preview keyframe
/// replaces, with the preview keyframe (appended when new). The reference a fresh solve uses.
std::vector<effects::Keyframe> preview_keyframe_list(const PreviewTarget& target);

class PreviewInterpolant {
 public:
  /// `options` for the scratch set (the document's: synchronous in replay and tests).
  explicit PreviewInterpolant(effects::KeyframeSetOptions options = {}) : options_(options) {}

  /// Brings the interpolant to `target` (re-seeding or one incremental move) and returns it.
  std::shared_ptr<const effects::RbfInterpolator> update(const PreviewTarget& target);
  /// Drops the scratch set (the preview ended).
  void reset();

  /// Seeds, the seeds that ran a full O(N^3) solve (no source, or a source without an exact
  /// state), and incremental moves so far, for tests and benchmarks.
  std::uint64_t seeds() const { return seeds_; }
  std::uint64_t full_seeds() const { return full_seeds_; }
  std::uint64_t moves() const { return moves_; }

 private:
  void seed(const PreviewTarget& target, std::vector<std::size_t> dropped);
  /// The seed from target.source: clone, drop, then one add or move; false when an edit of the
  /// clone did not go as a fresh list would (then seed() solves).
  bool seed_by_clone(const PreviewTarget& target, const std::vector<std::size_t>& dropped);

  effects::KeyframeSetOptions options_;
  std::unique_ptr<effects::KeyframeSet> set_;
  // what the set was seeded from
  std::vector<effects::Keyframe> base_;
  std::uint64_t revision_ = 0;
  std::optional<std::size_t> moved_;
  int effect_ = -1, dimension_ = 0;
  std::vector<double> neutral_;
  effects::InterpolationSettings settings_;
  double fps_ = 0.0;
  std::vector<std::size_t> dropped_;  //!< indices into base_ left out
  std::size_t index_ = 0;             //!< the preview keyframe's index in the set
  effects::Keyframe current_;         //!< the preview keyframe as the set has it
  std::uint64_t seeds_ = 0, full_seeds_ = 0, moves_ = 0;
};

}  // namespace vdfx::app
