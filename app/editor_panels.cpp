/// @file
/// @brief EditorPanels: building and placing the effect and timeline panels.
#include "app/editor_panels.h"

#include <glm/gtc/quaternion.hpp>

namespace vdfx::app {

using effects::EffectType;

xr::Pose anchor_pose(Anchor anchor, const xr::InputState& input) {
  switch (anchor) {
    case Anchor::LeftHand: return input.left.grip;
    case Anchor::RightHand: return input.right.grip;
    case Anchor::Head: return input.head;
    case Anchor::World: break;
  }
  return {};
}

namespace {
// A tilt about x so that a panel held below the eyes faces them.
xr::Pose offset(glm::dvec3 p, double tilt_deg = 0.0) {
  return {p, glm::angleAxis(glm::radians(tilt_deg), glm::dvec3(1.0, 0.0, 0.0))};
}
constexpr int kEffectW = 1000, kEffectH = 1500;
constexpr int kTimelineW = 2000, kTimelineH = 1200;
}  // namespace

PanelPlacement effect_panel_placement(PanelLayout layout) {
  // Desktop: the sim's left hand rests at (-0.2, -0.3, -0.3) m in the head frame looking where
  // the head looks, so this puts the panel at (-0.2, 0, -0.45) m from the eye: left of the view
  // centre (9.5 to 36 degrees), fully inside a 90-degree 16:9 view, and close enough that its
  // text stays legible in the desktop mirror's reduced eye buffers.
  if (layout == PanelLayout::Desktop) return {Anchor::LeftHand, offset({0.0, 0.3, -0.15})};
  return {Anchor::LeftHand, offset({0.05, 0.16, -0.05}, -20.0)};
}

PanelPlacement timeline_panel_placement(PanelLayout layout) {
  // Desktop: right of and below the view centre at 0.55 m (2 to 41 degrees right, 1 up to 26
  // down), clear of the effect panel and large enough to read in the desktop mirror.
  if (layout == PanelLayout::Desktop) return {Anchor::Head, offset({0.27, -0.135, -0.55})};
  return {Anchor::RightHand, offset({-0.05, 0.12, -0.05}, -20.0)};
}

std::string effect_widget_id(EffectType type) { return std::string(effects::effect_name(type)); }

EditorPanels::EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count,
                           PanelLayout layout_)
    : layout(layout_),
      effect_place(effect_panel_placement(layout_)),
      timeline_place(timeline_panel_placement(layout_)) {
  using namespace ui;
  effect = std::make_unique<Panel>(kEffectPanelId, kEffectW, kEffectH,
                                   glm::dvec2(0.25, 0.25 * kEffectH / kEffectW), fonts);
  {
    Panel& p = *effect;
    const Theme& t = p.theme();
    Stack col(Rect{0, 0, kEffectW, kEffectH}.inset(40.0), t.gap);
    title = &p.add<Label>("title", "Effects", Label::Role::Title);
    title->set_rect(col.next(64));
    std::vector<std::string> names;
    for (const auto& s : effects::all_effect_specs()) {
      std::string n(s.name);
      n[0] = static_cast<char>(n[0] - 'a' + 'A');
      names.push_back(n);
    }
    menu = &p.add<MenuList>("effect_menu", names, static_cast<int>(EffectType::Exposure), t.row_height);
    menu->set_rect(col.next(6 * t.row_height + 16));
    effect_widget_rect_ = col.next(330);
    effect_widgets[0] = &p.add<Slider1D>("blur", "Blur", Axis{0.0, 10.0, 0.1, "%.1f", "\u00b0", ""}, 0.0, 0.0);
    effect_widgets[1] = &p.add<ColourWheel>("tint", "Tint");
    effect_widgets[2] = &p.add<Slider1D>("exposure", "Exposure", Axis{-8.0, 8.0, 0.1, "%+.1f", " stops", ""}, 0.0, 0.0);
    effect_widgets[3] = &p.add<Slider1D>("saturation", "Saturation", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 1.0, 1.0);
    effect_widgets[4] = &p.add<Slider1D>("contrast", "Contrast", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 1.0, 1.0);
    effect_widgets[5] = &p.add<Pad2D>("vignette", "Vignette", Axis{0.0, 180.0, 1.0, "%.0f", "\u00b0", "radius"},
                                      Axis{0.01, 180.0, 1.0, "%.0f", "\u00b0", "falloff"}, glm::dvec2(180.0, 0.01));
    const Rect row = col.next(t.row_height);
    undo = &p.add<Button>("undo", "\u2190 Undo");
    undo->set_rect(split_cols(row, 2, 0, t.gap));
    redo = &p.add<Button>("redo", "Redo \u2192");
    redo->set_rect(split_cols(row, 2, 1, t.gap));
    const Rect keys = col.next(t.row_height);
    delete_nearest = &p.add<Button>("delete_nearest", "Delete nearest");
    delete_nearest->set_rect(split_cols(keys, 2, 0, t.gap));
    deselect = &p.add<Button>("deselect", "Deselect");
    deselect->set_rect(split_cols(keys, 2, 1, t.gap));
    deselect->set_enabled(false);
    exponent = &p.add<Slider1D>("exponent", "Exponent \u03b1", Axis{0.1, 3.9, 0.1, "%.1f", "", ""}, 1.0, 1.0);
    exponent->set_rect(col.next(130));
    time_scale = &p.add<Slider1D>("time_scale", "Time scale c", Axis{0.1, 10.0, 0.1, "%.1f", "", ""}, 1.0, 1.0);
    time_scale->set_rect(col.next(130));
    status = &p.add<Label>("status", "", Label::Role::Small, Align::Left, true);
    status->set_rect(col.next(60));
  }
  timeline = std::make_unique<Panel>(kTimelinePanelId, kTimelineW, kTimelineH, glm::dvec2(0.5, 0.3), fonts);
  {
    Panel& p = *timeline;
    const Theme& t = p.theme();
    Stack col(Rect{0, 0, kTimelineW, kTimelineH}.inset(40.0), t.gap);
    Stack top(col.next(t.row_height), t.gap, Stack::Axis::Horizontal);
    play = &p.add<Button>("play", "", Icon::Play);
    play->set_rect(top.next(120));
    prev_key = &p.add<Button>("prev_key", "\u2190 Key");
    prev_key->set_rect(top.next(220));
    next_key = &p.add<Button>("next_key", "Key \u2192");
    next_key->set_rect(top.next(220));
    time = &p.add<Label>("time", "", Label::Role::Body, Align::Right, true);
    time->set_rect(top.rest());
    strip = &p.add<TimelineStrip>("strip", static_cast<int>(frame_count));
    strip->set_rect(col.next(220));
    Stack toggles(col.next(t.row_height), t.gap, Stack::Axis::Horizontal);
    show_tracks = &p.add<Toggle>("show_tracks", "Track plot", true);
    show_tracks->set_rect(toggles.next(560));
    show_minimap = &p.add<Toggle>("show_minimap", "Minimap", true);
    show_minimap->set_rect(toggles.next(520));
    lock = &p.add<Toggle>("lock", "Lock in world", false);
    lock->set_rect(toggles.rest());
    hint = &p.add<Label>("hint", "", Label::Role::Small, Align::Left, true);
    hint->set_rect(col.next(56));
    const Rect bottom = col.rest();
    plot_rect_ = {bottom.x, bottom.y, 1000, bottom.h};
    minimap_rect_ = {bottom.x + 1000 + t.gap, bottom.y, bottom.w - 1000 - t.gap, bottom.h};
    plot = &p.add<Plot>("track_plot", "Value over time at the view", 0.0, 1.0, "%.1f");
    plot->set_rect(plot_rect_);
    minimap = &p.add<Minimap>("minimap", "Value over the sphere");
    minimap->set_rect(minimap_rect_);
  }
  show_effect(EffectType::Exposure);
}

void EditorPanels::show_effect(EffectType type) {
  for (std::size_t i = 0; i < effect_widgets.size(); ++i)
    effect_widgets[i]->set_rect(i == static_cast<std::size_t>(type) ? effect_widget_rect_ : ui::Rect{});
  menu->select(static_cast<int>(type));
}

void EditorPanels::place(const xr::InputState& input) {
  if (effect_place.anchor != Anchor::World)
    effect->set_world_pose(anchor_pose(effect_place.anchor, input) * effect_place.offset);
  if (timeline_place.anchor != Anchor::World)
    timeline->set_world_pose(anchor_pose(timeline_place.anchor, input) * timeline_place.offset);
  plot->set_rect(show_tracks->on() ? plot_rect_ : ui::Rect{});
  minimap->set_rect(show_minimap->on() ? minimap_rect_ : ui::Rect{});
}

std::vector<ui::Panel*> EditorPanels::reachable_by(xr::Hand hand) {
  const Anchor own = hand == xr::Hand::Left ? Anchor::LeftHand : Anchor::RightHand;
  std::vector<ui::Panel*> out;
  if (effect_place.anchor != own) out.push_back(effect.get());
  if (timeline_place.anchor != own) out.push_back(timeline.get());
  return out;
}

void EditorPanels::lock_timeline(bool locked) {
  timeline_place = locked ? PanelPlacement{Anchor::World, timeline->pose()} : timeline_panel_placement(layout);
  lock->set_on(locked);
}

}  // namespace vdfx::app
