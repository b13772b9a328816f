/// @file
/// @brief The editor's document: the sidecar being authored, one KeyframeSet per edit target (the
/// six stack effects, the first flare, the first grain: app/editor/edit_target.h), the tool's
/// chosen parameter values per target, and the undo stack over all of them.
///
/// Every edit goes through here, becomes one undo step (or part of an open group) and notifies
/// the change listener (autosave). The sidecar written is rebuilt from the keyframe sets, with
/// the effects in the stack's order (blur, tint, exposure, saturation, contrast, vignette); an
/// effect is written when it has keyframes or its own interpolation settings. The sidecar's first
/// flare and first grain are edited (keyframes, interpolation, flare style and light, grain
/// style); one is written when it existed, has keyframes or its own settings, or was given a
/// style or light; further flares and grains are carried through unchanged, after it.
///
/// Anchors (effects/anchor.h): each target's keyframe directions are stored in its anchor's
/// frame, resolved against the sidecar's camera and tracks (carried through unchanged). The
/// editor turns the view into that frame before it places, moves or picks a keyframe
/// (anchor_frames(t).apply) and back to show one (unapply); interpolator() evaluates each stack
/// effect at the view turned by its anchor.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/editor/edit_target.h"
#include "app/editor/pending_edit.h"
#include "app/editor/undo_stack.h"
#include "effects/anchor_sources.h"
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

  const effects::KeyframeSet& keyframe_set(EditTarget t) const { return *sets_[idx(t)]; }
  const std::vector<effects::Keyframe>& keyframes(EditTarget t) const {
    return sets_[idx(t)]->keyframes();
  }
  /// Effective settings: the target's override, else the file's default.
  effects::InterpolationSettings interpolation(EditTarget t) const;
  const std::optional<effects::InterpolationSettings>& interpolation_override(EditTarget t) const {
    return overrides_[idx(t)];
  }
  /// The tool's chosen values for a target (flat vector, EditTarget::params() layout; neutral
  /// at start).
  const std::vector<double>& params(EditTarget t) const { return params_[idx(t)]; }
  /// The latest solutions of the six stack effects (possibly one edit behind while async), each
  /// with its anchor.
  effects::StackInterpolator interpolator() const;
  /// A target's anchor ("video" unless the sidecar or set_anchor said otherwise) and its
  /// rotation at every frame.
  const effects::Anchor& anchor(EditTarget t) const { return anchors_[idx(t)]; }
  const effects::AnchorFrames& anchor_frames(EditTarget t) const { return frames_[idx(t)]; }
  /// The sidecar's camera and tracks, as anchors resolve them.
  effects::AnchorSources anchor_sources() const;

  /// The flare being edited (the sidecar's first) without its keyframes, interpolation and anchor
  /// (those are keyframes(EditTarget::flare()), its override and anchor()): style, light (a fixed
  /// one is a direction of the anchor's frame), settings. While the
  /// sidecar has none, the flare a first edit makes: directional, auto light, default settings.
  effects::FlareEffect flare() const { return flare_.value_or(new_flare()); }
  /// The grain effect being edited, likewise (a new one: surface style, seed 0).
  effects::GrainEffect grain() const { return grain_.value_or(effects::GrainEffect{}); }
  static effects::FlareEffect new_flare();

  // ---- edits: each is one undo step, or part of the open group
  /// Adds (or, within 0.5 deg at the same frame, replaces) a keyframe. Returns its index.
  effects::KeyframeSet::Edit add_keyframe(EditTarget t, const effects::Keyframe& keyframe);
  /// Moves a keyframe; one it lands on (within 0.5 deg at the same frame) is removed, like a
  /// placement replaces it. Returns where the moved keyframe now is and what it replaced. Moving
  /// a keyframe to where it is already is no edit.
  effects::KeyframeSet::Edit move_keyframe(EditTarget t, std::size_t index,
                                           const effects::Direction& direction, std::int64_t frame);
  void remove_keyframe(EditTarget t, std::size_t index);
  /// A keyframe's values (clamped; tint normalised); equal values are no edit.
  void set_keyframe_params(EditTarget t, std::size_t index, std::vector<double> params);
  /// The tool's values (clamped to the target's ranges; tint normalised).
  void set_params(EditTarget t, std::vector<double> params);
  /// The target's own exponent and time scale (throws io::InputError when out of range).
  void set_interpolation(EditTarget t, const effects::InterpolationSettings& settings);
  /// The flare's style; a plane distance at the old style's default moves to the new one's.
  void set_flare_style(effects::FlareStyle style);
  /// The flare's light: a fixed direction ("Set light here") or auto.
  void set_flare_light(const effects::FlareLight& light);
  void set_grain_style(effects::GrainStyle style);
  /// What a target's keyframes are fixed to. Each keyframe keeps where it shows at its own frame
  /// (its direction is turned from the old anchor's frame into the new one's there), and so does
  /// a fixed flare light at frame 0. Throws io::InputError when the anchor names a camera or track
  /// the sidecar lacks.
  void set_anchor(EditTarget t, const effects::Anchor& anchor);

  // ---- the camera and the subject tracks (app/editor/document_sources.cpp): one undo step each
  const std::optional<effects::CameraMotion>& camera() const { return camera_; }
  const std::vector<effects::SubjectTrack>& tracks() const { return tracks_; }
  /// The track of that name, or null.
  const effects::SubjectTrack* track(std::string_view name) const;
  /// Sets the camera's orientation at every frame (replacing one there was). Throws
  /// io::InputError when it has not one orientation per video frame.
  void set_camera(effects::CameraMotion camera);
  /// Adds the track, or replaces the one of its name; effects anchored to it follow the new one.
  /// Throws io::InputError for an invalid name, no points, or points outside the video's frames.
  void put_track(effects::SubjectTrack track);
  /// Removes the track; effects anchored to it go back to the video frame first, each keyframe
  /// (and a fixed flare light) staying where it shows at its own frame. One undo step, "delete
  /// track NAME". Returns how many effects were anchored to it. Throws io::InputError when there
  /// is no track of that name.
  int remove_track(const std::string& name);
  /// Renames the track and every anchor naming it (keyframes untouched: the track is the same).
  /// One undo step, "rename track FROM to TO"; returns how many effects were anchored to it.
  /// Throws io::InputError when there is no track FROM, TO is not a track name or is taken.
  int rename_track(const std::string& from, const std::string& to);

  // ---- the edit being made (app/editor/pending_edit.h): at most one at a time
  /// Starts one (a new keyframe, or keyframe `moved` held) and returns it; replaces any other.
  PendingEdit& begin_pending(EditTarget t, std::optional<std::size_t> moved, effects::Keyframe key);
  PendingEdit* pending() { return pending_.get(); }
  const PendingEdit* pending() const { return pending_.get(); }
  /// Commits it as one edit (add_keyframe, or move_keyframe of the held one to where it is) and
  /// ends it. Returns the edit; nullopt without a pending edit.
  std::optional<effects::KeyframeSet::Edit> commit_pending();
  /// Ends it without an edit.
  void cancel_pending() { pending_.reset(); }
  const PendingStats& pending_stats() const { return pending_stats_; }

  void begin_group(const std::string& label) { undo_.begin_group(label); }
  /// Closing the outermost group tells the change listener once about the changes made in it.
  void end_group();
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

  /// Clamps a flat parameter vector to the target's ranges (tint: also normalised).
  static std::vector<double> clamp_params(EditTarget t, std::vector<double> params);

 private:
  static std::size_t idx(EditTarget t) { return static_cast<std::size_t>(t.index()); }
  EffectSnapshot snapshot(EditTarget t) const;
  void restore(EditTarget t, const EffectSnapshot& s);
  void rebuild(EditTarget t, std::vector<effects::Keyframe> keyframes);
  /// frames_ from anchors_ (throws io::InputError naming the target whose anchor names what the
  /// sidecar lacks).
  void resolve_anchors();
  void record(const std::string& label, EditTarget t, EffectSnapshot before);
  SourcesSnapshot sources() const { return {camera_, tracks_}; }
  /// The targets anchored to the track of that name.
  std::vector<EditTarget> anchored_to(const std::string& track_name) const;
  /// Runs `body` (its changes) as one undo step named `label`; returns what it returns.
  int one_step(const std::string& label, const std::function<int()>& body);
  /// Puts the camera and tracks back and re-resolves the anchors (undo, redo: after the step).
  void restore(const SourcesSnapshot& s);
  void record(const std::string& label, SourcesSnapshot before);
  void changed();

  io::VideoInfo video_;
  /// Undo or redo is putting a step back: anchors are resolved once, after it (document.cpp).
  bool restoring_step_ = false;
  effects::InterpolationSettings defaults_;
  /// The sidecar's camera and tracks (what anchors turn by), each target's anchor and its frames.
  std::optional<effects::CameraMotion> camera_;
  std::vector<effects::SubjectTrack> tracks_;
  std::array<effects::Anchor, EditTarget::kCount> anchors_{};
  std::array<effects::AnchorFrames, EditTarget::kCount> frames_{};
  /// The edited flare's style, light and settings (nullopt: the sidecar has none yet) and the
  /// sidecar's further flares, written back unchanged after it. Likewise the grain effects.
  std::optional<effects::FlareEffect> flare_;
  std::vector<effects::FlareEffect> more_flares_;
  std::optional<effects::GrainEffect> grain_;
  std::vector<effects::GrainEffect> more_grains_;
  DocumentOptions options_;
  std::array<std::unique_ptr<effects::KeyframeSet>, EditTarget::kCount> sets_;
  std::array<std::optional<effects::InterpolationSettings>, EditTarget::kCount> overrides_;
  std::array<std::vector<double>, EditTarget::kCount> params_;
  UndoStack undo_;
  std::uint64_t revision_ = 0;
  PendingStats pending_stats_;
  std::unique_ptr<PendingEdit> pending_;  //!< after the sets: it reads them
  std::function<void()> listener_;
  bool unheard_ = false;  //!< changed inside an open group since the listener was last called
};

}  // namespace vdfx::app
