/// @file
/// @brief The editor's document: the sidecar being authored, one KeyframeSet per effect, the
/// tool's chosen parameter values per effect, and the undo stack over all of them.
///
/// Every edit goes through here, becomes one undo step (or part of an open group) and notifies
/// the change listener (autosave). The sidecar written is rebuilt from the keyframe sets, with
/// the effects in the stack's order (blur, tint, exposure, saturation, contrast, vignette); an
/// effect is written when it has keyframes or its own interpolation settings. Flares and grain
/// are carried through unchanged.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/pending_edit.h"
#include "app/undo_stack.h"
#include "effects/keyframe_set.h"
#include "effects/stack_interpolator.h"
#include "io/sidecar.h"

namespace vdfx::app {

struct DocumentOptions {
  //! Keyframe solves; replay and tests use {.async = false} so results are deterministic.
  effects::KeyframeSetOptions keyframes{};
};

class Document {
 public:
  /// Throws io::InputError when the sidecar's keyframes cannot be solved (bad settings).
  explicit Document(io::Sidecar sidecar, DocumentOptions options = {});

  const io::VideoInfo& video() const { return video_; }
  const effects::InterpolationSettings& default_interpolation() const { return defaults_; }
  /// The sidecar as it stands now.
  io::Sidecar sidecar() const;

  const effects::KeyframeSet& keyframe_set(effects::EffectType type) const { return *sets_[idx(type)]; }
  const std::vector<effects::Keyframe>& keyframes(effects::EffectType type) const {
    return sets_[idx(type)]->keyframes();
  }
  /// Effective settings: the effect's override, else the file's default.
  effects::InterpolationSettings interpolation(effects::EffectType type) const;
  const std::optional<effects::InterpolationSettings>& interpolation_override(effects::EffectType type) const {
    return overrides_[idx(type)];
  }
  /// The tool's chosen values for an effect (flat vector, EffectSpec layout; neutral at start).
  const std::vector<double>& params(effects::EffectType type) const { return params_[idx(type)]; }
  /// The latest solutions of every effect (possibly one edit behind while async).
  effects::StackInterpolator interpolator() const;

  // ---- edits: each is one undo step, or part of the open group
  /// Adds (or, within 0.5 deg at the same frame, replaces) a keyframe. Returns its index.
  effects::KeyframeSet::Edit add_keyframe(effects::EffectType type, const effects::Keyframe& keyframe);
  /// Moves a keyframe; one it lands on (within 0.5 deg at the same frame) is removed, like a
  /// placement replaces it. Returns where the moved keyframe now is and what it replaced. Moving
  /// a keyframe to where it is already is no edit.
  effects::KeyframeSet::Edit move_keyframe(effects::EffectType type, std::size_t index,
                                           const effects::Direction& direction, std::int64_t frame);
  void remove_keyframe(effects::EffectType type, std::size_t index);
  /// A keyframe's values (clamped; tint normalised); equal values are no edit.
  void set_keyframe_params(effects::EffectType type, std::size_t index, std::vector<double> params);
  /// The tool's values (clamped to the effect's ranges; tint normalised).
  void set_params(effects::EffectType type, std::vector<double> params);
  /// The effect's own exponent and time scale (throws io::InputError when out of range).
  void set_interpolation(effects::EffectType type, const effects::InterpolationSettings& settings);

  // ---- the edit being made (app/pending_edit.h): at most one at a time
  /// Starts one (a new keyframe, or keyframe `moved` held) and returns it; replaces any other.
  PendingEdit& begin_pending(effects::EffectType type, std::optional<std::size_t> moved, effects::Keyframe key);
  PendingEdit* pending() { return pending_.get(); }
  const PendingEdit* pending() const { return pending_.get(); }
  /// Commits it as one edit (add_keyframe, or move_keyframe of the held one to where it is) and
  /// ends it. Returns the edit; nullopt without a pending edit.
  std::optional<effects::KeyframeSet::Edit> commit_pending();
  /// Ends it without an edit.
  void cancel_pending() { pending_.reset(); }
  const PendingStats& pending_stats() const { return pending_stats_; }

  void begin_group(const std::string& label) { undo_.begin_group(label); }
  void end_group() { undo_.end_group(); }
  bool undo();
  bool redo();
  const UndoStack& undo_stack() const { return undo_; }

  /// Grows with every change of the document (edits, undo, redo).
  std::uint64_t revision() const { return revision_; }
  /// Grows whenever a published solution changes (an edit, or an asynchronous solve finishing):
  /// the sum of the effects' solution versions.
  std::uint64_t solutions_version() const;
  /// Called after every change (autosave).
  void set_change_listener(std::function<void()> listener) { listener_ = std::move(listener); }

  /// Clamps a flat parameter vector to the effect's ranges (tint: also normalised).
  static std::vector<double> clamp_params(effects::EffectType type, std::vector<double> params);

 private:
  static std::size_t idx(effects::EffectType t) { return static_cast<std::size_t>(t); }
  EffectSnapshot snapshot(effects::EffectType type) const;
  void restore(effects::EffectType type, const EffectSnapshot& s);
  void rebuild(effects::EffectType type, std::vector<effects::Keyframe> keyframes);
  void record(const std::string& label, effects::EffectType type, EffectSnapshot before);
  void changed();

  io::VideoInfo video_;
  effects::InterpolationSettings defaults_;
  /// The sidecar's flares, kept as read and written back unchanged (the editor does not edit
  /// them yet; a save must not drop them).
  std::vector<effects::FlareEffect> flares_;
  std::vector<effects::GrainEffect> grains_;  //!< likewise the grain effects
  DocumentOptions options_;
  std::array<std::unique_ptr<effects::KeyframeSet>, effects::kEffectCount> sets_;
  std::array<std::optional<effects::InterpolationSettings>, effects::kEffectCount> overrides_;
  std::array<std::vector<double>, effects::kEffectCount> params_;
  UndoStack undo_;
  std::uint64_t revision_ = 0;
  PendingStats pending_stats_;
  std::unique_ptr<PendingEdit> pending_;  //!< after the sets: it reads them
  std::function<void()> listener_;
};

}  // namespace vdfx::app
