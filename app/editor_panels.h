/// @file
/// @brief The editor's two panels (ui/): the effect panel and the timeline panel, their widgets
/// and where they sit.
///
/// Effect panel (non-dominant, left hand): title, effect menu (all six effects), the current
/// effect's widget (tint: colour wheel; vignette: 2-D pad radius x falloff; blur, exposure,
/// saturation, contrast: a slider with the contract's range), undo / redo, delete (the selected
/// keyframe, else the nearest) and deselect, and the
/// system menu: the current effect's exponent and time scale, autosave status.
/// Timeline panel (dominant, right hand): play/pause, previous / next keyframe, time, timeline
/// strip with keyframe markers, toggles for the effect track plot, the minimap and lock in world,
/// the plot and the minimap.
///
/// Layouts: Hands (a headset: the effect panel on the left grip, the timeline on the right grip,
/// each used with the OTHER hand's aim ray) and Desktop (the sim: the left "hand" rests in front
/// of the head, so the effect panel on it is head-locked; the timeline panel is placed relative to
/// the head too; the mouse-driven right aim ray reaches both).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "effects/effect_types.h"
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

struct PanelPlacement {
  Anchor anchor = Anchor::LeftHand;
  xr::Pose offset;  //!< panel centre relative to the anchor
};

/// Default placements of the two panels for a layout.
PanelPlacement effect_panel_placement(PanelLayout layout);
PanelPlacement timeline_panel_placement(PanelLayout layout);

class EditorPanels {
 public:
  EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count, PanelLayout layout);

  /// Moves the panels to their anchors (locked panels stay).
  void place(const xr::InputState& input);
  /// Shows only the current effect's widget and selects it in the menu.
  void show_effect(effects::EffectType type);
  /// Both panels, in hit-test order.
  std::vector<ui::Panel*> all() { return {effect.get(), timeline.get()}; }
  /// The panels the given hand's aim ray may use: those not anchored to that hand.
  std::vector<ui::Panel*> reachable_by(xr::Hand hand);
  /// Locks the timeline panel in the world where it is now, or re-attaches it to its anchor.
  void lock_timeline(bool locked);

  PanelLayout layout;
  std::unique_ptr<ui::Panel> effect, timeline;
  PanelPlacement effect_place, timeline_place;

  // effect panel
  ui::Label* title = nullptr;
  ui::MenuList* menu = nullptr;
  //! One widget per effect, indexed by EffectType; only the current one has a rectangle.
  std::array<ui::Widget*, effects::kEffectCount> effect_widgets{};
  ui::Button* undo = nullptr;
  ui::Button* redo = nullptr;
  ui::Button* delete_nearest = nullptr;  //!< deletes the selected keyframe, else the nearest
  ui::Button* deselect = nullptr;        //!< leaves the selected keyframe (right thumbstick click too)
  ui::Slider1D* exponent = nullptr;
  ui::Slider1D* time_scale = nullptr;
  ui::Label* status = nullptr;

  // timeline panel
  ui::Button* play = nullptr;
  ui::Button* prev_key = nullptr;
  ui::Button* next_key = nullptr;
  ui::Label* time = nullptr;
  ui::TimelineStrip* strip = nullptr;
  ui::Toggle* show_tracks = nullptr;
  ui::Toggle* show_minimap = nullptr;
  ui::Toggle* lock = nullptr;
  ui::Plot* plot = nullptr;
  ui::Minimap* minimap = nullptr;
  ui::Label* hint = nullptr;

 private:
  ui::Rect effect_widget_rect_;
  ui::Rect plot_rect_, minimap_rect_;
};

/// Widget ids of the per-effect widgets ("blur", "tint", ...: the effect's sidecar name).
std::string effect_widget_id(effects::EffectType type);

}  // namespace vdfx::app
