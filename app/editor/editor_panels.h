/// @file
/// @brief The editor's panels (ui/): their widgets, where they sit, what the editor's state looks
/// like on them (show: the one writer of the widgets) and what their widgets are for (control_of:
/// their events become editor actions in app/editor/panel_binding.h).
///
/// Effect panel: title, effect menu (the six effects, Flare and Grain, in two columns), the
/// current effect's widget (tint: colour wheel; vignette: 2-D pad radius x falloff; blur,
/// exposure, saturation, contrast, flare intensity: a slider with the contract's range; grain:
/// intensity and size sliders), its options (flare: style switch, "Set light here", auto light;
/// grain: style switch), undo / redo, delete (the selected keyframe, else the nearest) and
/// deselect, the current effect's exponent and time scale, autosave status.
/// Timeline panel: play/pause, previous / next keyframe, time, the timeline strip with video
/// thumbnails and keyframe markers.
/// Track plot and minimap, with toggles for both and for locking the timeline in the world: on
/// the timeline panel (Hands) or on a panel of their own (Desktop, "views").
///
/// Layouts:
/// - Hands (a headset): the effect panel on the left grip, the timeline panel on the right grip,
///   each used with the OTHER hand's aim ray.
/// - Desktop (the sim on a monitor): every panel is head-locked and placed on a rectangle of the
///   desktop view's window pixels (xr::desktop_view): effect panel down the left edge, timeline
///   along the bottom, plot and minimap at the top right, a heads-up line at the top centre; the
///   view centre (where keyframes are placed) stays clear. Each panel is rendered at the
///   resolution it covers on screen (ui::Panel::set_render_scale), so text is rasterised at its
///   on-screen size. set_viewport() follows the window.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/editor/edit_target.h"
#include "app/editor/editor_view.h"
#include "app/editor/rename_keyboard.h"
#include "app/editor/track_marker.h"
#include "app/editor/track_section.h"
#include "effects/effect_types.h"
#include "effects/flare.h"
#include "effects/grain.h"
#include "effects/keyframe.h"
#include "ui/button.h"
#include "ui/colour_wheel.h"
#include "ui/menu_list.h"
#include "ui/minimap.h"
#include "ui/panel.h"
#include "ui/plot.h"
#include "ui/slider.h"
#include "ui/timeline_strip.h"
#include "xr/input/actions.h"

namespace vdfx::app {

enum class PanelLayout { Hands, Desktop };
enum class Anchor { LeftHand, RightHand, Head, World };

/// The pose a panel is anchored to (World: identity).
xr::Pose anchor_pose(Anchor anchor, const xr::InputState& input);

inline constexpr const char* kEffectPanelId = "effects";
inline constexpr const char* kTimelinePanelId = "timeline";
inline constexpr const char* kViewsPanelId = "views";  //!< Desktop: plot, minimap, toggles
inline constexpr const char* kHudPanelId = "hud";      //!< Desktop: the heads-up line

struct PanelPlacement {
  Anchor anchor = Anchor::LeftHand;
  xr::Pose offset;  //!< panel centre relative to the anchor
};

/// The desktop view the Desktop layout fills: window pixels and horizontal FOV.
struct DesktopViewport {
  int width = 1280;
  int height = 720;
  double hfov_deg = 100.0;
  bool operator==(const DesktopViewport&) const = default;
};

/// A panel's rectangle in the desktop view's window pixels (origin top-left).
struct ScreenRect {
  int x = 0, y = 0, w = 0, h = 0;
};

/// Screen pixels per layout pixel of the Desktop layout's panels in a viewport: 0.4 at the
/// default 1280 x 720 (the smallest text, 34 layout px, is then 14 px tall), growing with the
/// window so the panels keep their share of it.
double desktop_ui_scale(const DesktopViewport& v);

/// Where a head-locked quad must sit (centre, metres, head frame) and how large it must be to
/// cover `r` exactly in the desktop view of `v`, at `distance_m` in front of the eye.
PanelPlacement desktop_placement(const DesktopViewport& v, const ScreenRect& r, double distance_m,
                                 glm::dvec2* size_m);

/// What a widget of the panels is for: panel_binding turns its events into editor actions.
enum class PanelControl {
  None,          //!< labels, or a widget of another effect
  EffectMenu,    //!< the effect menu
  EffectValues,  //!< the current effect's widget (the grain's two sliders)
  Exponent,
  TimeScale,
  FlareStyle,
  SetLight,
  AutoLight,
  GrainStyle,
  Undo,
  Redo,
  Delete,
  Deselect,
  Minimap,  //!< a keyframe dot pressed
  Play,
  PreviousKey,
  NextKey,
  Strip,
  ShowTrackPlot,
  ShowMinimap,
  LockTimeline,
  Suggest,          //!< "Suggest ..." (or, while one runs, its cancel)
  SuggestStrength,  //!< the strength beside it
  TrackSubject,     //!< "Track subject" (app/editor/track_section.h), or its cancel
  TrackCamera,      //!< "Track camera", or its cancel
  TrackCorrect,     //!< "Correct here": the shown track re-tracked from the view centre
  TrackAnchor,      //!< the current effect's anchor: the next one
  TrackDelete,      //!< "Delete NAME": the shown track removed
  TrackRename,      //!< "Rename NAME": the on-screen keyboard opened on the shown track
  RenameKey,        //!< one of its keys (RenameKeyboard::key_of)
  RenameCancel,
  RenameCommit,
};

class EditorPanels {
 public:
  EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count,
               PanelLayout layout, DesktopViewport viewport = {});

  /// Shows the editor's state: the only writer of the widgets (besides the UI pointers' own
  /// interaction: hover, press, focus, a held widget's value). The current effect's widgets are
  /// laid out and selected in the menu; a widget the pointer holds keeps its own value; the
  /// visualizations are taken over when their versions moved. Setters compare, so an unchanged
  /// view costs no redraw.
  void show(const EditorView& view);
  /// Moves the panels to their anchors (locked panels stay).
  void place(const xr::InputState& input);
  /// Desktop: the window changed; panels are re-placed, re-sized and re-scaled for it.
  void set_viewport(const DesktopViewport& viewport);
  const DesktopViewport& viewport() const { return viewport_; }
  /// Locks the timeline panel in the world where it is now, or re-attaches it to its anchor.
  void lock_timeline(bool locked);
  PanelLayout layout() const { return layout_; }
  /// Where a panel is anchored (kEffectPanelId, ...); a Hands layout has no views or HUD panel.
  const PanelPlacement& placement(std::string_view panel_id) const;
  /// Desktop: where each panel covers the window (for tests and screenshots); empty for Hands.
  ScreenRect screen_rect(std::string_view panel_id) const;

  /// What `widget` is for while `target` is shown (PanelControl::None: nothing to do).
  PanelControl control_of(const ui::Widget* widget, EditTarget target) const;
  /// The values (flat) an event of one of `target`'s value widgets sets, the others kept from
  /// `current`: the slider's value, the pad's two, the wheel's hue and saturation as normalised
  /// tint gains, the grain's intensity or size.
  std::vector<double> values_of(EditTarget target, const ui::Event& event,
                                std::span<const double> current) const;

  /// Every panel, in hit-test order (to render them and hit-test them).
  std::vector<ui::Panel*> all();
  /// The panel with this id, or null.
  ui::Panel* panel(std::string_view id);
  const ui::Panel* panel(std::string_view id) const;
  /// The panels the given hand's aim ray may use: those not anchored to that hand.
  std::vector<ui::Panel*> reachable_by(xr::Hand hand);

  // ---- the widgets, to read (tests, recordings' scripts)
  const ui::Label& title() const { return *title_; }
  const ui::MenuList& menu() const { return *menu_; }
  /// The target's main widget (its slider, the tint wheel, the vignette pad).
  const ui::Widget& effect_widget(EditTarget target) const {
    return *effect_widgets_[static_cast<std::size_t>(target.index())];
  }
  const ui::Button& undo_button() const { return *undo_; }
  const ui::Button& deselect_button() const { return *deselect_; }
  const ui::Button& suggest_button() const { return *suggest_; }
  const ui::TimelineStrip& strip() const { return *strip_; }
  const TrackSection& track_section() const { return track_; }
  const TrackMarker& track_marker() const { return *marker_; }
  const RenameKeyboard& rename_keyboard() const { return *keyboard_; }
  const ui::Plot& plot() const { return *plot_; }
  const ui::Minimap& minimap() const { return *minimap_; }
  const ui::Toggle& minimap_toggle() const { return *show_minimap_; }
  /// Desktop: the heads-up line; null for Hands.
  const ui::Label* hud_line() const { return hud_line_; }

 private:
  void build_effect_panel(std::shared_ptr<const ui::FontSet> fonts, int width, int height,
                          glm::dvec2 size_m);
  void build_hands_timeline(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frames);
  void build_desktop_panels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frames);
  void add_visualizations(ui::Panel& p, ui::Stack& col, double toggles_h, bool stacked);
  void add_transport_row(ui::Panel& p, ui::Stack& col);
  // show(), in parts
  void show_effect(EditTarget target);
  void show_values(EditTarget target, std::span<const double> values);
  void show_effect_panel(const EditorView& view);
  void show_timeline(const EditorView& view);
  void show_visualizations(const EditorView& view);

  PanelLayout layout_;
  std::unique_ptr<ui::Panel> effect_, timeline_;
  std::unique_ptr<ui::Panel> views_, hud_;  //!< Desktop only
  PanelPlacement effect_place_, timeline_place_, views_place_, hud_place_;

  // effect panel
  ui::Label* title_ = nullptr;
  ui::MenuList* menu_ = nullptr;
  //! One (main) widget per target, indexed by EditTarget::index(); only the current target's
  //! widgets have rectangles.
  std::array<ui::Widget*, EditTarget::kCount> effect_widgets_{};
  // The same, typed.
  ui::Slider1D* blur_ = nullptr;
  ui::ColourWheel* tint_ = nullptr;
  ui::Slider1D* exposure_ = nullptr;
  ui::Slider1D* saturation_ = nullptr;
  ui::Slider1D* contrast_ = nullptr;
  ui::Pad2D* vignette_ = nullptr;
  ui::Slider1D* flare_intensity_ = nullptr;
  ui::MenuList* flare_style_ = nullptr;  //!< Headset | Directional (effects::FlareStyle order)
  ui::Button* set_light_ = nullptr;      //!< "Set light here": the light at the view centre
  ui::Toggle* auto_light_ = nullptr;     //!< the light found in each video frame
  ui::Slider1D* grain_intensity_ = nullptr;
  ui::Slider1D* grain_size_ = nullptr;
  ui::MenuList* grain_style_ = nullptr;  //!< effects::kGrainStyles order, two columns
  ui::Button* undo_ = nullptr;
  ui::Button* redo_ = nullptr;
  ui::Button* delete_nearest_ = nullptr;  //!< deletes the selected keyframe, else the nearest
  ui::Button* deselect_ = nullptr;  //!< leaves the selected keyframe (right thumbstick click too)
  ui::Slider1D* exponent_ = nullptr;
  ui::Slider1D* time_scale_ = nullptr;  //!< degrees of view one second of video weighs like
  ui::Slider1D* suggest_strength_ =
      nullptr;                     //!< 0..1, beside "Suggest" (app/editor/suggest_worker.h)
  ui::Button* suggest_ = nullptr;  //!< "Suggest exposure" / guidance / comfort; cancel
  ui::Label* status_ = nullptr;

  TrackSection track_;  //!< Desktop: on the views panel; Hands: on the timeline panel
  std::unique_ptr<TrackMarker> marker_;  //!< the shown track in the view (no input)
  /// Shown while a track is renamed: over the view (Desktop); Hands: in the world where it was
  /// opened, keyboard_offset_ from the head then (not head-locked: it would swim with the head).
  std::unique_ptr<RenameKeyboard> keyboard_;
  PanelPlacement keyboard_place_;
  xr::Pose keyboard_offset_;

  // timeline panel
  ui::Button* play_ = nullptr;
  ui::Button* prev_key_ = nullptr;
  ui::Button* next_key_ = nullptr;
  ui::Label* time_ = nullptr;
  ui::TimelineStrip* strip_ = nullptr;
  ui::Label* hint_ = nullptr;  //!< Hands: the status line under the strip (Desktop: the HUD)

  // plot and minimap (timeline panel for Hands, views panel for Desktop)
  ui::Toggle* show_tracks_ = nullptr;
  ui::Toggle* show_minimap_ = nullptr;
  ui::Toggle* lock_ = nullptr;
  ui::Plot* plot_ = nullptr;
  ui::Minimap* minimap_ = nullptr;

  // heads-up panel (Desktop)
  ui::Label* hud_line_ = nullptr;     //!< frame, time, heading, effect, selection, frame rate
  ui::Label* hud_message_ = nullptr;  //!< the latest message (expires), or what to do now

  DesktopViewport viewport_;
  ui::Rect effect_widget_rect_, options_rect_;
  ui::Rect plot_rect_, minimap_rect_;
  /// The versions of what show() took over last (EditorView::thumbnails_version, the
  /// visualizations'): 0, nothing yet.
  struct Shown {
    std::uint64_t thumbnails = 0, markers = 0, track = 0, field = 0;
  };
  Shown shown_;
};

/// Widget ids of the per-target main widgets ("blur", "tint", ..., "flare", "grain": the sidecar
/// name).
std::string effect_widget_id(EditTarget target);

}  // namespace vdfx::app
