/// @file
/// @brief The in-headset editor without GL: turns OpenXR-style actions into edits of a Document
/// and says what to render (stack parameters, panels, status).
///
/// Per frame the GL loop calls update(input, t_ns) with the frame's input snapshot and display
/// time, then current_params() (or params_for_view per eye/pixel) for the effect stack, panels()
/// for the quad layers (Panel::texture() renders a panel's CPU image only when it changed) and
/// status_text() for the mirror window. Time is passed in, never read, so replay is exact.
///
/// Bindings (docs/editor.md): right trigger on nothing = preview, release = place a keyframe at
/// the view centre and the current frame; trigger on a panel = UI. Right B held = unaltered film.
/// Right A = delete the selected keyframe, else the one nearest the view. Left X / Y = undo /
/// redo. A press on a keyframe's minimap dot, or the previous / next keyframe buttons, select
/// that keyframe. Right squeeze = grab: holds the selected keyframe (without a selection, selects
/// the one nearest the view); while held it follows the view (keeping its offset from the view
/// centre) and the playhead (keeping its offset in frames); release commits one move. A selected keyframe's values show in the effect widget,
/// which then edits them. Right thumbstick click (or the Deselect button, or a trigger press on
/// nothing, which then previews a new keyframe) deselects. Each hand's aim ray drives the panels
/// not attached to that hand (ui::Pointer).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "app/autosave.h"
#include "app/document.h"
#include "app/editor_panels.h"
#include "app/editor_preview.h"
#include "app/minimap_worker.h"
#include "effects/effect_types.h"
#include "io/frame_time.h"
#include "ui/interaction.h"
#include "xr/actions.h"

namespace vdfx::app {

struct EditorOptions {
  PanelLayout layout = PanelLayout::Hands;
  /// Desktop layout: the desktop view the panels are laid out in (set_viewport follows a window).
  DesktopViewport viewport;
  std::shared_ptr<const ui::FontSet> fonts;  //!< null: ui::FontSet::load() (DejaVu)
  double marker_cone_deg = 30.0;             //!< timeline markers highlighted within this angle of the view
  int track_samples = 240;                   //!< frames sampled for the effect-track plot
  int minimap_width = 128;
  int minimap_height = 64;
  bool loop = true;                          //!< playback wraps at the end
  double view_hfov_deg = 90.0;               //!< the view footprint drawn on the minimap (Hands;
  double view_vfov_deg = 90.0;               //!< Desktop: the viewport's)
  //! true (`vdfx edit`): the minimap is computed on a worker (MinimapWorker) and shown a frame
  //! or two late; the frame thread never waits for it. false (replay, tests): computed in
  //! update(), so every run shows the same pictures.
  bool async_visualizations = false;
  //! Autosave every change to this sidecar path (+ a recovery copy, removed by finish()).
  std::optional<std::filesystem::path> autosave_path;
};

class Editor {
 public:
  Editor(io::Sidecar sidecar, DocumentOptions document_options = {}, EditorOptions options = {});

  /// One frame: input at display time t_ns (non-decreasing between calls).
  void update(const xr::InputState& input, std::int64_t t_ns);

  // ---- what to render
  /// Stack parameters at the head's view direction and the current frame, preview and
  /// "unaltered" (B) included.
  effects::StackParams current_params() const { return params_for_view(view_, frame_); }
  /// The same at any direction (per-eye centres, per-pixel mode): while the trigger previews,
  /// the interpolant is the one with the preview keyframe at the view centre.
  effects::StackParams params_for_view(const effects::Direction& direction, std::int64_t frame) const;
  /// The panels for quad layers, with world poses (Panel::pose()) and textures (Panel::texture()).
  std::vector<ui::Panel*> panels();
  std::string status_text() const;
  /// The heads-up line (Desktop): frame, time, heading, effect, selection, frame rate.
  std::string hud_text() const;
  /// Under it: the latest message while it lasts (kMessageLifetimeNs), else what to do now.
  std::string hud_message() const;
  /// Messages (placed, undone, ...) show this long (display time), then go.
  static constexpr std::int64_t kMessageLifetimeNs = 4'000'000'000;
  bool unaltered() const { return unaltered_; }
  bool previewing() const { return previewing_; }
  /// The current effect's selected keyframe (index into its keyframes), if any.
  const std::optional<std::size_t>& selected_keyframe() const { return selected_; }
  /// Whether the selected keyframe is held by the grab (right squeeze).
  bool grabbing() const { return grabbing_; }
  /// While grabbing: where the grabbed keyframe would land now (its values included), else the
  /// selected keyframe as it is; nullopt without a selection.
  std::optional<effects::Keyframe> selected_preview() const;
  bool playing() const { return playing_; }
  std::int64_t frame() const { return frame_; }
  const effects::Direction& view_direction() const { return view_; }
  /// The input of the last update.
  const xr::InputState& input() const { return input_; }
  /// A hand's UI pointer (what its ray hits, the widget under it).
  const ui::Pointer& pointer(xr::Hand hand) const { return hand == xr::Hand::Left ? left_ptr_ : right_ptr_; }
  effects::EffectType current_effect() const { return effect_; }
  /// Where the last keyframe jump asks the user to look (cleared once the view is within 5 deg).
  const std::optional<effects::Direction>& look_target() const { return look_target_; }

  // ---- the window around the editor
  /// Desktop layout: the window's size or FOV changed; the panels follow.
  void set_viewport(const DesktopViewport& viewport);
  /// What the frame loop measures, for the heads-up line: frames per second, and whether the
  /// video is still loading (no frame decoded yet).
  void set_loop_status(double frames_per_second, bool video_loading);

  // ---- actions (panels and bindings call these; so can tests)
  void select_effect(effects::EffectType type);
  /// The current effect's chosen values (one undo step unless a group is open).
  void set_chosen_params(std::vector<double> params);
  void set_playing(bool on);
  void seek(std::int64_t frame);
  /// Jumps to the previous (-1) / next (+1) keyframe's frame and selects that keyframe (not
  /// while grabbing); returns its direction.
  std::optional<effects::Direction> jump_to_keyframe(int step);
  /// Deletes the current effect's keyframe nearest the view (RBF distance); false when none.
  bool delete_nearest();
  /// Places the chosen values at the view centre and the current frame (replaces a keyframe
  /// within 0.5 deg on the same frame).
  void place_keyframe();
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

  /// Clean exit: final save, recovery copy removed. False when saving failed.
  bool finish();
  /// The autosave line for the UI ("" without autosave).
  std::string autosave_status() const { return autosave_ ? autosave_->status() : std::string(); }

  Document& document() { return doc_; }
  const Document& document() const { return doc_; }
  EditorPanels& ui() { return panels_; }
  /// The live preview's interpolant (its seed and move counters: tests, benchmarks).
  const PreviewInterpolant& preview() const { return preview_; }

  // ---- visualization data (kept up to date by update). While a keyframe is previewed (placed,
  // or grabbed away from its place) the minimap field and the track are the preview
  // interpolant's (the one params_for_view answers with), else the document's.
  const cv::Mat& minimap_field() const { return minimap_; }
  const std::vector<double>& track_values() const { return track_; }
  const std::vector<std::int64_t>& track_frames() const { return track_frames_; }
  /// Indices of the current effect's keyframes within marker_cone_deg of the view.
  const std::vector<std::size_t>& near_keyframes() const { return near_; }
  /// How often each visualization was recomputed (they follow changes, not frames); with
  /// async_visualizations, the minimap fields taken over from the worker.
  int minimap_computations() const { return minimap_count_; }
  /// Whether the minimap shown is the one for the current keyframes, effect and frame (always
  /// after update() without async_visualizations).
  bool minimap_current() const { return minimap_key_ == minimap_requested_; }
  /// Waits for the minimap worker to finish and shows its field (frame thread; tests, replays).
  /// Returns minimap_current(). Immediate without async_visualizations.
  bool wait_for_visualizations(std::chrono::milliseconds timeout);
  int marker_computations() const { return marker_count_; }

 private:
  void handle(const ui::Event& e);
  void say(std::string message);
  void sync_widgets();
  void refresh_visualizations();
  void show_minimap(const MinimapKey& key, cv::Mat field);
  std::vector<double> widget_params(const ui::Event& e) const;
  /// What the preview interpolates now (placement or grab); nullopt when neither.
  std::optional<PreviewTarget> preview_target() const;
  /// preview_target() when the preview changes the interpolant (placing, or a grab that moved
  /// its keyframe); nullopt when the document's interpolant is the one shown.
  std::optional<PreviewTarget> shown_preview_target() const;
  /// The values the effect widget shows and edits: the selected keyframe's, else the chosen.
  const std::vector<double>& widget_values() const;
  /// After undo/redo: drops the selection when the keyframe count changed (indices renumbered).
  void keep_selection_if_stable(std::size_t count_before);
  void validate_selection();

  Document doc_;
  EditorOptions options_;
  std::unique_ptr<Autosave> autosave_;
  EditorPanels panels_;
  ui::Pointer left_ptr_, right_ptr_;
  io::Rational fps_;

  xr::InputState input_;
  std::optional<std::int64_t> last_t_;
  effects::Direction view_{};
  std::int64_t frame_ = 0;
  effects::EffectType effect_ = effects::EffectType::Exposure;
  bool previewing_ = false, unaltered_ = false, playing_ = false;
  bool right_was_down_ = false;  //!< the right pointer's trigger (ui hysteresis) at the last update
  // selection and grab
  std::optional<std::size_t> selected_;
  bool grabbing_ = false;
  effects::Direction grab_view0_{};  //!< the view when the grab began
  std::int64_t grab_frame0_ = 0;     //!< the playhead then
  effects::Keyframe grab_key0_;      //!< the keyframe's place then
  std::int64_t play_t0_ = 0, play_f0_ = 0, now_ = 0;
  std::optional<effects::Direction> look_target_;
  std::string message_;
  std::int64_t message_t_ = 0;  //!< display time the message was said
  double loop_fps_ = 0.0;
  bool video_loading_ = false;

  // visualization caches
  MinimapKey minimap_key_;        //!< what the minimap shown was computed for
  MinimapKey minimap_requested_;  //!< what it should show now
  MinimapKey track_key_;
  effects::Direction marker_view_{}, track_view_{};
  std::uint64_t marker_revision_ = ~0ull;
  int marker_effect_ = -1;
  std::int64_t marker_selected_ = -1;  //!< the selected keyframe's (held) frame at the last marker update
  std::optional<std::size_t> nearest_;  //!< nearest keyframe at the last minimap update
  //! The preview keyframe (placement: moved = nullopt; grab: the held index) the minimap and
  //! track last showed; nullopt while they show the document's interpolant.
  struct ShownPreview {
    std::optional<std::size_t> moved;
    effects::Keyframe key;
  };
  std::optional<ShownPreview> shown_preview_;
  std::uint64_t preview_serial_ = 0;  //!< grows when it changes (MinimapKey::preview)
  cv::Mat minimap_;
  std::vector<double> track_;
  std::vector<std::int64_t> track_frames_;
  std::vector<std::size_t> near_;
  int minimap_count_ = 0, marker_count_ = 0;
  std::unique_ptr<MinimapWorker> minimap_worker_;  //!< with async_visualizations
  // preview interpolant for directions other than the view centre: seeded once per preview,
  // then one O(N^2) move per frame in which the preview keyframe moved
  mutable PreviewInterpolant preview_;
};

}  // namespace vdfx::app
