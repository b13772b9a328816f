/// @file
/// @brief The editor's panels (ui/): their widgets and where they sit.
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
#include "xr/actions.h"

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

class EditorPanels {
 public:
  EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count,
               PanelLayout layout, DesktopViewport viewport = {});

  /// Moves the panels to their anchors (locked panels stay).
  void place(const xr::InputState& input);
  /// Desktop: the window changed; panels are re-placed, re-sized and re-scaled for it.
  void set_viewport(const DesktopViewport& viewport);
  const DesktopViewport& viewport() const { return viewport_; }
  /// Desktop: where each panel covers the window (for tests and screenshots); empty for Hands.
  ScreenRect screen_rect(std::string_view panel_id) const;
  /// Shows only the current target's widgets and selects it in the menu.
  void show_effect(EditTarget target);
  /// Shows a target's values (flat, EditTarget::params() layout) on its widgets; a widget the
  /// pointer holds keeps its own value, and the wheel keeps its hue and saturation unless the
  /// gains moved them (tint normalisation would nudge a held wheel).
  void show_values(EditTarget target, std::span<const double> values);
  /// Whether `widget` is one of the widgets that set `target`'s values.
  bool edits_values(EditTarget target, const ui::Widget* widget) const;
  /// The values (flat) an event of one of `target`'s value widgets sets, the others kept from
  /// `current`: the slider's value, the pad's two, the wheel's hue and saturation as normalised
  /// tint gains, the grain's intensity or size.
  std::vector<double> values_of(EditTarget target, const ui::Event& event,
                                std::span<const double> current) const;
  /// The flare's and the grain's options as the document has them (style, light).
  void show_options(const effects::FlareEffect& flare, const effects::GrainEffect& grain);
  /// Every panel, in hit-test order.
  std::vector<ui::Panel*> all();
  /// The panel with this id, or null.
  ui::Panel* panel(std::string_view id);
  /// The panel holding a widget, or null.
  ui::Panel* panel_of(const ui::Widget* widget);
  /// The panels the given hand's aim ray may use: those not anchored to that hand.
  std::vector<ui::Panel*> reachable_by(xr::Hand hand);
  /// Locks the timeline panel in the world where it is now, or re-attaches it to its anchor.
  void lock_timeline(bool locked);

  PanelLayout layout;
  std::unique_ptr<ui::Panel> effect, timeline;
  std::unique_ptr<ui::Panel> views, hud;  //!< Desktop only
  PanelPlacement effect_place, timeline_place, views_place, hud_place;

  // effect panel
  ui::Label* title = nullptr;
  ui::MenuList* menu = nullptr;
  //! One (main) widget per target, indexed by EditTarget::index(); only the current target's
  //! widgets have rectangles.
  std::array<ui::Widget*, EditTarget::kCount> effect_widgets{};
  // The same, typed.
  ui::Slider1D* blur = nullptr;
  ui::ColourWheel* tint = nullptr;
  ui::Slider1D* exposure = nullptr;
  ui::Slider1D* saturation = nullptr;
  ui::Slider1D* contrast = nullptr;
  ui::Pad2D* vignette = nullptr;
  ui::Slider1D* flare_intensity = nullptr;
  ui::MenuList* flare_style = nullptr;  //!< Headset | Directional (effects::FlareStyle order)
  ui::Button* set_light = nullptr;      //!< "Set light here": the light at the view centre
  ui::Toggle* auto_light = nullptr;     //!< the light found in each video frame
  ui::Slider1D* grain_intensity = nullptr;
  ui::Slider1D* grain_size = nullptr;
  ui::MenuList* grain_style = nullptr;  //!< effects::kGrainStyles order, two columns
  ui::Button* undo = nullptr;
  ui::Button* redo = nullptr;
  ui::Button* delete_nearest = nullptr;  //!< deletes the selected keyframe, else the nearest
  ui::Button* deselect = nullptr;  //!< leaves the selected keyframe (right thumbstick click too)
  ui::Slider1D* exponent = nullptr;
  ui::Slider1D* time_scale = nullptr;  //!< degrees of view one second of video weighs like
  ui::Label* status = nullptr;

  // timeline panel
  ui::Button* play = nullptr;
  ui::Button* prev_key = nullptr;
  ui::Button* next_key = nullptr;
  ui::Label* time = nullptr;
  ui::TimelineStrip* strip = nullptr;
  ui::Label* hint = nullptr;  //!< Hands: the status line under the strip (Desktop: the HUD)

  // plot and minimap (timeline panel for Hands, views panel for Desktop)
  ui::Toggle* show_tracks = nullptr;
  ui::Toggle* show_minimap = nullptr;
  ui::Toggle* lock = nullptr;
  ui::Plot* plot = nullptr;
  ui::Minimap* minimap = nullptr;

  // heads-up panel (Desktop)
  ui::Label* hud_line = nullptr;     //!< frame, time, heading, effect, selection, frame rate
  ui::Label* hud_message = nullptr;  //!< the latest message (expires), or what to do now

 private:
  void build_effect_panel(std::shared_ptr<const ui::FontSet> fonts, int width, int height,
                          glm::dvec2 size_m);
  void build_hands_timeline(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frames);
  void build_desktop_panels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frames);
  void add_visualizations(ui::Panel& p, ui::Stack& col, double toggles_h, bool stacked);
  void add_transport_row(ui::Panel& p, ui::Stack& col);

  DesktopViewport viewport_;
  ui::Rect effect_widget_rect_, options_rect_;
  ui::Rect plot_rect_, minimap_rect_;
};

/// Widget ids of the per-target main widgets ("blur", "tint", ..., "flare", "grain": the sidecar
/// name).
std::string effect_widget_id(EditTarget target);

}  // namespace vdfx::app
