/// @file
/// @brief The in-headset editor without GL: turns OpenXR-style actions into edits of a Document
/// and says what to render (stack parameters, panels, status).
///
/// Per frame the GL loop calls update(input, t_ns) with the frame's input snapshot and display
/// time, then current_params() (or params_for_view per eye/pixel) for the effect stack, panels()
/// for the quad layers and status_text() for the window title. Time is passed in, never read, so
/// replay is exact.
///
/// One way round (docs/editor.md, "Shape", has the picture): EditorControls
/// (app/editor/editor_controls.h) turns the input's edges into UI events and the binding table's
/// commands; panel_binding (app/editor/panel_binding.h) turns each UI event into a call of one
/// of the actions below; the actions edit the Document (app/editor/document.h) and its
/// PendingEdit (app/editor/pending_edit.h: the keyframe being placed or held, with the whole
/// grab); VisualizationCache (app/editor/visualization_cache.h) computes the plot, minimap and
/// markers as data; and once a frame view() gathers it all into one EditorView that
/// EditorPanels::show writes onto the widgets. What stays here: the playhead, the view, the
/// current effect, the selection, what the views panel shows, and the messages.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/autosave.h"
#include "app/editor/document.h"
#include "app/editor/editor_controls.h"
#include "app/editor/editor_panels.h"
#include "app/editor/editor_view.h"
#include "app/editor/suggest_worker.h"
#include "app/editor/track_worker.h"
#include "app/editor/visualization_cache.h"
#include "effects/effect_types.h"
#include "io/frame_time.h"
#include "xr/input/actions.h"

namespace vdfx::app {

struct EditorOptions {
  PanelLayout layout = PanelLayout::Hands;
  /// Desktop layout: the desktop view the panels are laid out in (set_viewport follows a window).
  DesktopViewport viewport;
  std::shared_ptr<const ui::FontSet> fonts;  //!< null: ui::FontSet::load() (DejaVu)
  VisualizationOptions visuals;              //!< minimap, track plot, markers
  bool loop = true;                          //!< playback wraps at the end
  //! Autosave every change to this sidecar path (+ a recovery copy, removed by finish()).
  std::optional<std::filesystem::path> autosave_path;
  //! Read-only (another editor has the sidecar open, app/editor/edit_access.h): what the heads-up
  //! line and the status say, in front ("READ-ONLY: ..."); autosave_path is then a copy that
  //! only a change creates. Empty: the sidecar is this session's.
  std::string read_only_note;
  /// The video "Suggest" meters (docs/suggest.md, "In the editor"); none: no suggestions.
  std::optional<std::filesystem::path> video;
  /// Suggestions run on a worker; false: within the update that starts them (replays are exact).
  bool async_suggestions = true;
};

class Editor {
 public:
  Editor(io::Sidecar sidecar, DocumentOptions document_options = {}, EditorOptions options = {});

  /// One frame: input at display time t_ns (non-decreasing between calls).
  void update(const xr::InputState& input, std::int64_t t_ns);

  // ---- what to render
  /// Stack parameters at the head's view direction and the current frame, the pending edit and
  /// "unaltered" (right b) included.
  effects::StackParams current_params() const { return params_for_view(view_, play_.frame); }
  /// The same at any direction (per-eye centres, per-pixel mode): while a keyframe is placed or
  /// held, the current effect's interpolant is the pending edit's.
  effects::StackParams params_for_view(const effects::Direction& direction,
                                       std::int64_t frame) const;
  /// params_for_view at one frame for many directions (the per-pixel bake): without a pending
  /// edit of a stack effect, the anchored effects' centres are turned once for the frame
  /// (effects::StackAtFrame). Valid until the next update().
  std::function<effects::StackParams(const effects::Direction&)> params_at(
      std::int64_t frame) const;
  /// The panels for quad layers, with world poses (Panel::pose()) and textures (Panel::texture()).
  std::vector<ui::Panel*> panels() { return panels_.all(); }
  /// One of them by id (kEffectPanelId, ...), or null.
  ui::Panel* panel(std::string_view id) { return panels_.panel(id); }
  /// Everything the panels show, as of now (update() shows it once a frame).
  EditorView view() const;
  std::string status_text() const;
  /// The heads-up line (Desktop): frame, time, heading, effect, selection, frame rate.
  std::string hud_text() const;
  /// Under it: the latest message while it lasts (kMessageLifetimeNs), else what to do now.
  std::string hud_message() const;
  /// Messages (placed, undone, ...) show this long (display time), then go.
  static constexpr std::int64_t kMessageLifetimeNs = 4'000'000'000;

  bool unaltered() const { return unaltered_; }
  /// A new keyframe is being placed (it follows the view until the trigger is let go).
  bool previewing() const { return doc_.pending() && !doc_.pending()->moved(); }
  /// The selected keyframe is held (right squeeze).
  bool grabbing() const { return doc_.pending() && doc_.pending()->moved(); }
  /// The current effect's selected keyframe (index into its keyframes), if any.
  const std::optional<std::size_t>& selected_keyframe() const { return selected_; }
  /// While grabbing: where the held keyframe would land now (its values included), else the
  /// selected keyframe as it is; nullopt without a selection.
  std::optional<effects::Keyframe> selected_preview() const;
  /// The values the effect widget shows and edits: the selected keyframe's, else the chosen.
  const std::vector<double>& widget_values() const;
  bool playing() const { return play_.playing; }
  std::int64_t frame() const { return play_.frame; }
  const effects::Direction& view_direction() const { return view_; }
  /// The input of the last update.
  const xr::InputState& input() const { return input_; }
  EditTarget current_effect() const { return effect_; }
  /// A target's interpolant as shown now: the pending edit's while one of its keyframes is
  /// placed or held, else the document's solution (null or empty: no keyframes).
  std::shared_ptr<const effects::RbfInterpolator> interpolant(EditTarget target) const;
  /// A hand's UI pointer (what its ray hits, the widget under it).
  const ui::Pointer& pointer(xr::Hand hand) const { return controls_.pointer(hand); }

  // ---- the window around the editor
  /// Desktop layout: the window's size or FOV changed; the panels follow.
  void set_viewport(const DesktopViewport& viewport);
  /// What the frame loop measures, for the heads-up line: frames per second, and whether the
  /// video is still loading (no frame decoded yet).
  void set_loop_status(double frames_per_second, bool video_loading);
  /// Video thumbnails for the timeline strip (ThumbnailWorker's), shown from the next frame.
  void set_thumbnails(std::vector<cv::Mat> thumbnails);

  // ---- actions (the bindings and the panels call these; so can tests)
  void select_effect(EditTarget target);
  /// The flare's style (one undo step).
  void set_flare_style(effects::FlareStyle style);
  /// "Set light here": the flare's light becomes the view centre (one undo step).
  void set_light_here();
  /// The flare's light found in each video frame (on), or fixed at the view centre (off).
  void set_auto_light(bool on);
  void set_grain_style(effects::GrainStyle style);
  /// The current effect's chosen values (one undo step unless a group is open).
  void set_chosen_params(std::vector<double> params);
  /// What the effect widget edits: the selected keyframe's values, else the chosen ones.
  void set_widget_values(std::vector<double> values);
  /// The current effect's own exponent / time scale (in degrees of view per second of video,
  /// docs/interpolation.md), written as its interpolation override (one undo step unless a
  /// group is open).
  void set_exponent(double exponent);
  void set_time_scale_deg_per_s(double deg_per_s);
  /// A gesture (a drag, a thumbstick push) is one undo step: the edits between these are one
  /// group, labelled `label`.
  void begin_gesture(const std::string& label);
  void end_gesture();
  void set_playing(bool on);
  void seek(std::int64_t frame);
  /// Jumps to the previous (-1) / next (+1) keyframe's frame and selects that keyframe (not
  /// while grabbing); returns its direction.
  std::optional<effects::Direction> jump_to_keyframe(int step);
  /// Deletes the selected keyframe, else the current effect's keyframe nearest the view (RBF
  /// distance); false when none.
  bool delete_nearest();
  /// Places the chosen values at the view centre and the current frame (replaces a keyframe
  /// within 0.5 deg on the same frame).
  void place_keyframe();
  /// Starts previewing a new keyframe at the view centre (a selection is left first).
  void begin_preview();
  /// Selects the current effect's keyframe nearest the view (RBF distance); false when none.
  bool select_nearest();
  /// Selects the current effect's keyframe `index` (the minimap dot pressed, the keyframe
  /// jumped to); false when there is none such or a grab is in progress.
  bool select_keyframe(std::size_t index);
  void deselect();
  /// Holds the selected keyframe (without a selection, selects the nearest first): until
  /// grab_release() it follows the view and the playhead by how far they moved since the grab
  /// began. False when there is none.
  bool grab();
  /// Commits the grab as one undoable move (none when it did not move); the keyframe stays
  /// selected. Landing within 0.5 deg of another keyframe at the same frame replaces that one.
  void grab_release();
  /// The selected keyframe's values (one undo step unless a group is open).
  void set_selected_params(std::vector<double> params);
  bool undo();
  bool redo();
  /// "Suggest" for the current effect (suggest_kind_for): proposes its keyframes from the video
  /// at the strength set, off the frame thread; when done they are added as one undo step. While
  /// a suggestion runs, the same action cancels it (the document stays as it was).
  void suggest();
  /// 0..1: how much of each suggestion to apply (the slider beside "Suggest").
  void set_suggest_strength(double strength);
  double suggest_strength() const { return suggest_strength_; }
  /// The suggestion running: how far it is (0..1); nullopt when none runs.
  std::optional<double> suggestion_progress() const;
  /// Waits for the running suggestion and adds its keyframes (tests); false on timeout.
  bool wait_for_suggestion(std::chrono::milliseconds timeout);
  // ---- tracking (app/editor/editor_track.cpp; docs/editor.md, "Tracking"). Each runs off the
  // frame thread; while one runs, any of them cancels it (the document stays as it was); when
  // done its result is one undo step.
  /// "Track subject": follows what is at the view centre at the current frame through the clip,
  /// as a new track ("subject1", "subject2", ...), which becomes the shown track.
  void track_subject();
  /// "Track camera": the camera's orientation at every frame (the world anchor's rotations).
  void track_camera();
  /// "Correct here": the shown track's subject is at the view centre at the current frame; it is
  /// tracked again from there (merge_correction keeps the earlier frames it saw).
  void correct_track();
  /// "Delete NAME": removes the shown track (one undo step); effects anchored to it go back to
  /// the video frame, their keyframes where they show.
  void delete_track();
  /// "Rename NAME": opens the on-screen keyboard (app/editor/rename_keyboard.h) on the shown
  /// track's name. rename_key types one key's text (a character, "Shift" or "Back");
  /// commit_rename renames the track and every anchor naming it (one undo step) and closes the
  /// keyboard, or says why not and keeps it open; cancel_rename closes it.
  void begin_rename();
  void rename_key(const std::string& key);
  void commit_rename();
  void cancel_rename();
  /// The current effect's anchor (one undo step); false, with the reason said, when refused (a
  /// world anchor without the camera's motion, a track that is not there, during a grab).
  bool set_anchor(const effects::Anchor& anchor);
  /// The anchor button: the next anchor the current effect may take (video, world when the
  /// camera was tracked, each track).
  void next_anchor();
  /// The run in progress: how far it is (0..1); nullopt when none runs.
  std::optional<double> tracking_progress() const;
  /// Waits for the running job and puts its result into the document (tests); false on timeout.
  bool wait_for_tracking(std::chrono::milliseconds timeout);
  /// The track drawn and corrected: the current effect's anchor track, else the last tracked or
  /// chosen, else the first; null when the sidecar has none.
  const effects::SubjectTrack* shown_track() const;
  TrackView track_view() const;

  /// Locks the timeline panel in the world, or back on its anchor.
  void lock_timeline(bool locked);
  /// Shows or hides the track plot / the minimap.
  void show_track_plot(bool on);
  void show_minimap(bool on);

  /// Clean exit: final save, recovery copy removed. False when saving failed.
  bool finish();
  /// The autosave line for the UI ("" without autosave).
  std::string autosave_status() const { return autosave_ ? autosave_->status() : std::string(); }
  /// Sidecar writes so far (each edit, or each group of edits such as a drag, once).
  int autosave_saves() const { return autosave_ ? autosave_->saves() : 0; }

  Document& document() { return doc_; }
  const Document& document() const { return doc_; }
  /// The panels, to read (they are written by update() only, from view()).
  const EditorPanels& ui() const { return panels_; }

  // ---- visualization data (VisualizationCache; kept up to date by update)
  const cv::Mat& minimap_field() const { return visuals_.minimap_field(); }
  const std::vector<double>& track_values() const { return visuals_.track_values(); }
  const std::vector<std::int64_t>& track_frames() const { return visuals_.track_frames(); }
  const std::vector<std::size_t>& near_keyframes() const { return visuals_.near_keyframes(); }
  int minimap_computations() const { return visuals_.minimap_computations(); }
  bool minimap_current() const { return visuals_.minimap_current(); }
  /// Waits for the minimap worker and shows its field (tests, replays); minimap_current().
  bool wait_for_visualizations(std::chrono::milliseconds timeout);

 private:
  void run(EditorCommand command);
  void say(std::string message);
  /// Advances the clock and the playhead to t_ns; returns the seconds since the last update.
  double advance(std::int64_t t_ns);
  /// What the visualizations are asked to show this frame.
  VisualizationInput visualization_input() const;
  /// Writes view() onto the panels; within update() only once, at its end.
  void show();
  /// The current effect's keyframe nearest the view (contract distance), if any.
  std::optional<std::size_t> nearest_to_view() const;
  /// Keeps the pending edit's keyframe where the view, the playhead and the values put it.
  void sync_pending();
  /// Takes a finished suggestion's keyframes into the document (one undo step) or says why not.
  void poll_suggestion();
  void apply_suggestion(EditTarget target, const std::string& label, const SuggestOutcome& outcome);
  /// Starts a tracking job (or cancels the one running) on a copy of the document's sidecar.
  void start_tracking(TrackJob job);
  /// Takes a finished tracking job's camera or track into the document (one undo step).
  void poll_tracking();
  /// After undo/redo: drops the selection when the keyframe count changed (indices renumbered).
  void keep_selection_if_stable(std::size_t count_before);
  void validate_selection();

  /// Where the playhead is and how it moves.
  struct Playhead {
    std::int64_t frame = 0;
    bool playing = false;
    std::int64_t t0 = 0, f0 = 0;  //!< display time and frame when play was pressed
    std::int64_t now = 0;         //!< the last update's display time
    std::optional<std::int64_t> last_t;
  };
  /// What the views panel shows and where the timeline is.
  struct Views {
    bool track_plot = true, minimap = true, timeline_locked = false;
  };
  /// Thumbnails for the timeline strip, and how often they were set.
  struct Thumbnails {
    std::vector<cv::Mat> images;
    std::uint64_t version = 0;
  };
  /// What the status lines say besides the model.
  struct Status {
    std::string message;
    std::int64_t message_t = 0;                     //!< display time it was said
    std::optional<effects::Direction> look_target;  //!< where a keyframe jump asks to look
    double loop_fps = 0.0;
    bool video_loading = false;
  };

  Document doc_;
  EditorOptions options_;
  std::unique_ptr<Autosave> autosave_;
  EditorPanels panels_;
  EditorControls controls_;
  VisualizationCache visuals_;
  io::Rational fps_;
  xr::InputState input_;
  effects::Direction view_{};
  EditTarget effect_ = effects::EffectType::Exposure;
  Playhead play_;
  /// The current effect's selected keyframe. While it is held (grabbing()), the document's
  /// PendingEdit holds it and keeps the rest of the grab.
  std::optional<std::size_t> selected_;
  Views views_;
  Thumbnails thumbnails_;
  Status status_;
  bool unaltered_ = false;
  bool updating_ = false;
  std::unique_ptr<SuggestWorker> suggesting_;                  //!< the suggestion running, if any
  EditTarget suggest_target_ = effects::EffectType::Exposure;  //!< what it is for
  double suggest_strength_ = 1.0;  //!< inside update(): the panels are shown once, at its end
  std::unique_ptr<TrackWorker> tracking_;  //!< the tracking job running, if any
  std::string track_name_;                 //!< the track last tracked or chosen
  RenameView rename_;                      //!< the rename being typed (open: the keyboard shows)
};

}  // namespace vdfx::app
