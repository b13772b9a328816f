/// @file
/// @brief Unlimited undo/redo of document edits as before/after snapshots of the effects touched.
///
/// Each step records, per effect it touched, the track (keyframes and interpolation override) and
/// the tool's chosen parameter values before and after. Undo restores the "before" snapshots,
/// redo the "after" ones, so an undo gives back exactly the sidecar bytes of before the edit.
/// A group (a slider drag between the UI's DragBegin and DragEnd) merges every change made while
/// it is open into one step.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/editor/edit_target.h"
#include "effects/anchor.h"
#include "effects/flare.h"
#include "effects/grain.h"
#include "effects/keyframe.h"

namespace vdfx::app {

/// What of one effect an edit can change.
struct EffectSnapshot {
  std::optional<effects::InterpolationSettings> interpolation;  //!< the effect's override
  std::vector<effects::Keyframe> keyframes;
  std::vector<double> params;  //!< the tool's chosen values for this effect
  effects::Anchor anchor;      //!< the frame the keyframes' directions are in
  /// The flare target: its entry's style, light and settings (keyframes and interpolation empty:
  /// they are the fields above); nullopt while the sidecar has no flare. Likewise the grain.
  std::optional<effects::FlareEffect> flare;
  std::optional<effects::GrainEffect> grain;
  bool operator==(const EffectSnapshot&) const = default;
};

struct EffectChange {
  EditTarget target = effects::EffectType::Exposure;
  EffectSnapshot before;
  EffectSnapshot after;
};

/// What anchors turn by: the sidecar's camera and subject tracks (the tracking panel edits them).
struct SourcesSnapshot {
  std::optional<effects::CameraMotion> camera;
  std::vector<effects::SubjectTrack> tracks;
  bool operator==(const SourcesSnapshot&) const = default;
};

struct SourcesChange {
  SourcesSnapshot before;
  SourcesSnapshot after;
};

/// One undo step.
struct UndoStep {
  std::string label;
  std::vector<EffectChange> changes;  //!< in the order they were made; undo reverts backwards
  /// The camera and tracks, when the step changed them: undo restores them after the effects
  /// (an anchor naming a track goes before the track), redo before.
  std::optional<SourcesChange> sources;
};

class UndoStack {
 public:
  /// Records a change: opens a new step (clearing redo) or, inside a group, merges into the
  /// group's step (the first "before" of an effect is kept, its "after" replaced). A change whose
  /// before equals its after is dropped.
  void push(const std::string& label, EffectChange change);
  /// The same for a change of the camera or the tracks.
  void push(const std::string& label, SourcesChange change);
  /// Opens a group; nested calls are counted. Changes until the matching end_group form one step.
  void begin_group(const std::string& label);
  void end_group();
  /// A group is open (a drag): the document tells its listener once, when it closes.
  bool in_group() const { return group_depth_ > 0; }

  bool can_undo() const { return !done_.empty(); }
  bool can_redo() const { return !undone_.empty(); }
  /// Moves the last step to the redo list and returns it (nullopt when there is none). Closes an
  /// open group first.
  std::optional<UndoStep> undo();
  std::optional<UndoStep> redo();
  std::size_t undo_size() const { return done_.size(); }
  std::size_t redo_size() const { return undone_.size(); }
  /// Label of the step undo() would revert ("" when none).
  std::string next_undo_label() const { return done_.empty() ? "" : done_.back().label; }
  /// Names the last step (a group's step takes its first change's label; a command made of
  /// several changes names the whole).
  void rename_last(const std::string& label) {
    if (!done_.empty()) done_.back().label = label;
  }

 private:
  std::vector<UndoStep> done_, undone_;
  int group_depth_ = 0;
  bool group_has_step_ = false;  //!< the open group already put its step on done_
};

}  // namespace vdfx::app
