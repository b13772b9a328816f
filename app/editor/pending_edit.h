/// @file
/// @brief The edit being made before it is committed: a new keyframe being placed (it follows the
/// view) or a keyframe being held (grabbed, it follows the view and the playhead). Owned by the
/// Document (Document::begin_pending); it is the grab's whole state (which keyframe is held,
/// where the view and the playhead were when it was grabbed, where it is now). The editor moves
/// it (follow), the renderer and the visualizations read its interpolant, and the editor commits
/// or cancels it.
///
/// Its interpolant is the document's keyframes of the effect with the pending keyframe where it
/// is now. A fresh RbfInterpolator per frame would be an O(N^3) solve (tens of ms at N = 1000);
/// instead a scratch effects::KeyframeSet is seeded once, by cloning the document's solved set
/// (KeyframeSet::clone: its exact incremental state, O(N^2), no solve) and one incremental add or
/// move, and every later change of the pending keyframe is one O(N^2) KeyframeSet::move (and
/// set_params when its values change). Only when the document's set has no exact state (merged
/// keyframes, an asynchronous re-solve still running) does the seed solve. Keyframes the pending
/// keyframe lands on (effects::replaces, the rule the commit will apply) are left out while it
/// sits there and come back when it moves off; that, an edit of the effect's keyframes or of its
/// settings re-seeds (rare while a keyframe is held). The result equals a fresh solve of the same
/// keyframes (tested to 1e-9).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "app/editor/edit_target.h"
#include "effects/keyframe_set.h"

namespace vdfx::app {

class Document;

/// Kept by the document over all its pending edits: the seeds, full-solve seeds and incremental
/// moves of their scratch sets (tests, benchmarks), and the serial their versions come from, so
/// that no two pending states of one document share a version.
struct PendingStats {
  std::uint64_t seeds = 0, full_seeds = 0, moves = 0;
  std::uint64_t serial = 0;
};

class PendingEdit {
 public:
  /// `moved`: the index of the held keyframe, nullopt for a new one; `key`: where the pending
  /// keyframe is, with its values.
  PendingEdit(const Document& document, EditTarget target, std::optional<std::size_t> moved,
              effects::Keyframe key, effects::KeyframeSetOptions options, PendingStats& stats);
  ~PendingEdit();
  PendingEdit(const PendingEdit&) = delete;
  PendingEdit& operator=(const PendingEdit&) = delete;

  EditTarget target() const { return target_; }
  /// The held keyframe's index; nullopt while placing a new one.
  const std::optional<std::size_t>& moved() const { return moved_; }
  const effects::Keyframe& key() const { return key_; }
  /// Moves the pending keyframe (or changes its values).
  void set_key(effects::Keyframe key);
  /// A held keyframe follows the view and the playhead by how far they moved since the hold
  /// began: this is where they were then (Editor::grab), and the key where it was.
  void hold_from(const effects::Direction& view, std::int64_t frame);
  /// Where the pending keyframe goes for this view and playhead: a new one at the view centre,
  /// with the target's chosen values; a held one (after hold_from) keeps the offsets it had from
  /// the view (in azimuth and altitude, clamped to +-90) and from the playhead (in frames,
  /// clamped to the clip), with the held keyframe's values as the document has them now. So
  /// holding alone moves nothing, and a keyframe held while looked at stays at the view centre.
  /// The view is a direction of the video frame at `frame`; the key's direction is stored in the
  /// target's anchor's frame (Document::anchor_frames: the view turned at `frame`).
  effects::Keyframe placed_at(const effects::Direction& view, std::int64_t frame) const;
  /// set_key(placed_at(view, frame)).
  void follow(const effects::Direction& view, std::int64_t frame) {
    set_key(placed_at(view, frame));
  }
  /// False while a held keyframe sits where it is in the document: the interpolant is then the
  /// document's.
  bool changes_interpolant() const;
  /// The effect's interpolant with the pending keyframe where it is now (brought up to date on
  /// demand: at most one incremental move per change); null when !changes_interpolant().
  std::shared_ptr<const effects::RbfInterpolator> interpolant() const;
  /// Grows whenever interpolant() would answer differently: the key moved or changed values while
  /// it changes the interpolant, or it began to; 0 while it does not.
  std::uint64_t version() const { return changes_interpolant() ? version_ : 0; }
  /// The keyframes the interpolant uses: the effect's, without those the pending keyframe
  /// replaces, with it (appended when new). What a fresh solve would take.
  std::vector<effects::Keyframe> keyframe_list() const;

 private:
  std::vector<std::size_t> replaced() const;
  void seed(std::vector<std::size_t> dropped) const;
  bool seed_by_clone(const std::vector<std::size_t>& dropped) const;

  const Document& doc_;
  EditTarget target_;
  std::optional<std::size_t> moved_;
  effects::Keyframe key_;
  /// Where the view and the playhead were when the hold began, and the key then.
  struct Hold {
    effects::Direction view{};
    std::int64_t frame = 0;
    effects::Keyframe key;
  };
  std::optional<Hold> hold_;
  std::uint64_t version_ = 0;
  bool was_changing_ = false;  //!< changes_interpolant() when the version last moved
  effects::KeyframeSetOptions options_;
  PendingStats& stats_;
  /// The scratch set and what it was seeded from (the document's revision and keyframes, the
  /// keyframes left out, where the pending keyframe is in it and as it has it).
  /// Brought up to date by the (logically const) interpolant().
  struct Scratch;
  mutable std::unique_ptr<Scratch> scratch_;
};

}  // namespace vdfx::app
