/// @file
/// @brief EditorPanels: building and placing the editor's panels in both layouts.
#include "app/editor_panels.h"

#include <algorithm>
#include <cmath>

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

// Hands layout (layout pixels; 1000 px = 0.25 m).
constexpr int kEffectW = 1000, kEffectH = 1500;
constexpr int kTimelineW = 2000, kTimelineH = 1200;

// Desktop layout (layout pixels, drawn at desktop_ui_scale()).
constexpr int kDeskEffectW = 800, kDeskEffectH = 1600;
constexpr int kDeskTimelineW = 2310, kDeskTimelineH = 560;
constexpr int kDeskViewsW = 800, kDeskViewsH = 1040;
constexpr int kDeskHudW = 1500, kDeskHudH = 110;
constexpr int kDeskMargin = 12;            //!< screen pixels between panels and the window edge
constexpr double kDeskDistanceM = 1.0;     //!< head-locked quads at this depth
/// Layout pixels the Desktop layout needs across and down the window at scale 1.
constexpr double kDeskLayoutW = 3200.0, kDeskLayoutH = 1800.0;

std::string title_case(std::string_view s) {
  std::string n(s);
  if (!n.empty()) n[0] = static_cast<char>(n[0] - 'a' + 'A');
  return n;
}

}  // namespace

double desktop_ui_scale(const DesktopViewport& v) {
  const double s = std::min(v.width / kDeskLayoutW, v.height / kDeskLayoutH);
  return std::clamp(s, 0.25, 1.0);
}

PanelPlacement desktop_placement(const DesktopViewport& v, const ScreenRect& r, double distance_m,
                                 glm::dvec2* size_m) {
  // The desktop camera's tangents (xr::desktop_view): square pixels, centred.
  const double tx = std::tan(0.5 * glm::radians(v.hfov_deg));
  const double ty = tx * v.height / v.width;
  const auto tan_x = [&](double px) { return -tx + px / v.width * 2.0 * tx; };
  const auto tan_y = [&](double py) { return ty - py / v.height * 2.0 * ty; };
  const double cx = tan_x(r.x + 0.5 * r.w), cy = tan_y(r.y + 0.5 * r.h);
  if (size_m)
    *size_m = {(tan_x(r.x + r.w) - tan_x(r.x)) * distance_m, (tan_y(r.y) - tan_y(r.y + r.h)) * distance_m};
  return {Anchor::Head, offset({cx * distance_m, cy * distance_m, -distance_m})};
}

std::string effect_widget_id(EffectType type) { return std::string(effects::effect_name(type)); }

EditorPanels::EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count,
                           PanelLayout layout_, DesktopViewport viewport)
    : layout(layout_), viewport_(viewport) {
  if (layout == PanelLayout::Hands) {
    build_effect_panel(fonts, kEffectW, kEffectH, glm::dvec2(0.25, 0.25 * kEffectH / kEffectW));
    build_hands_timeline(fonts, frame_count);
    effect_place = {Anchor::LeftHand, offset({0.05, 0.16, -0.05}, -20.0)};
    timeline_place = {Anchor::RightHand, offset({-0.05, 0.12, -0.05}, -20.0)};
  } else {
    build_effect_panel(fonts, kDeskEffectW, kDeskEffectH, glm::dvec2(0.2, 0.4));
    build_desktop_panels(fonts, frame_count);
    set_viewport(viewport);
  }
  show_effect(EffectType::Exposure);
}

void EditorPanels::build_effect_panel(std::shared_ptr<const ui::FontSet> fonts, int width, int height,
                                      glm::dvec2 size_m) {
  using namespace ui;
  effect = std::make_unique<Panel>(kEffectPanelId, width, height, size_m, fonts);
  Panel& p = *effect;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, static_cast<double>(width), static_cast<double>(height)}.inset(40.0), t.gap);
  title = &p.add<Label>("title", "Effects", Label::Role::Title);
  title->set_rect(col.next(64));
  std::vector<std::string> names;
  for (const auto& s : effects::all_effect_specs()) names.push_back(title_case(s.name));
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
  // In an author's unit: how many degrees of view one second of video weighs like
  // (docs/interpolation.md, "Time"), on a logarithmic track.
  Axis time_axis{0.1, 2000.0, 0.0, "%.2g", "\u00b0 of view", ""};
  time_axis.log = true;
  time_scale = &p.add<Slider1D>("time_scale", "1 s of video weighs like", time_axis,
                                effects::kAuthorDegPerSecond, effects::kAuthorDegPerSecond);
  time_scale->set_rect(col.next(130));
  status = &p.add<Label>("status", "", Label::Role::Small, Align::Left, true);
  status->set_rect(col.next(60));
}

void EditorPanels::add_visualizations(ui::Panel& p, ui::Stack& col, double toggles_h, bool stacked) {
  using namespace ui;
  const Theme& t = p.theme();
  if (stacked) {  // Desktop: two rows of toggles, then the minimap over the plot
    const Rect row = col.next(toggles_h);
    show_tracks = &p.add<Toggle>("show_tracks", "Track plot", true);
    show_tracks->set_rect(split_cols(row, 2, 0, t.gap));
    show_minimap = &p.add<Toggle>("show_minimap", "Minimap", true);
    show_minimap->set_rect(split_cols(row, 2, 1, t.gap));
    lock = &p.add<Toggle>("lock", "Lock timeline in world", false);
    lock->set_rect(col.next(toggles_h));
    const Rect rest = col.rest();
    minimap_rect_ = {rest.x, rest.y, rest.w, 0.5 * rest.w + 90.0};
    plot_rect_ = {rest.x, minimap_rect_.bottom() + t.gap, rest.w, rest.bottom() - minimap_rect_.bottom() - t.gap};
  } else {  // Hands: toggles in one row, the hint, then the plot beside the minimap
    Stack toggles(col.next(toggles_h), t.gap, Stack::Axis::Horizontal);
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
  }
  plot = &p.add<Plot>("track_plot", "Value over time at the view", 0.0, 1.0, "%.1f");
  plot->set_rect(plot_rect_);
  minimap = &p.add<Minimap>("minimap", "Value over the sphere");
  minimap->set_rect(minimap_rect_);
}

namespace {
/// The top row of the timeline: play, previous / next keyframe, the time label.
void transport_row(ui::Panel& p, ui::Stack& col, ui::Button*& play, ui::Button*& prev, ui::Button*& next,
                   ui::Label*& time) {
  using namespace ui;
  const Theme& t = p.theme();
  Stack top(col.next(t.row_height), t.gap, Stack::Axis::Horizontal);
  play = &p.add<Button>("play", "", Icon::Play);
  play->set_rect(top.next(120));
  prev = &p.add<Button>("prev_key", "\u2190 Key");
  prev->set_rect(top.next(220));
  next = &p.add<Button>("next_key", "Key \u2192");
  next->set_rect(top.next(220));
  time = &p.add<Label>("time", "", Label::Role::Body, Align::Right, true);
  time->set_rect(top.rest());
}
}  // namespace

void EditorPanels::build_hands_timeline(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frames) {
  using namespace ui;
  timeline = std::make_unique<Panel>(kTimelinePanelId, kTimelineW, kTimelineH, glm::dvec2(0.5, 0.3), fonts);
  Panel& p = *timeline;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, kTimelineW, kTimelineH}.inset(40.0), t.gap);
  transport_row(p, col, play, prev_key, next_key, time);
  strip = &p.add<TimelineStrip>("strip", static_cast<int>(frames));
  strip->set_rect(col.next(220));
  add_visualizations(p, col, t.row_height, false);
}

void EditorPanels::build_desktop_panels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frames) {
  using namespace ui;
  timeline = std::make_unique<Panel>(kTimelinePanelId, kDeskTimelineW, kDeskTimelineH, glm::dvec2(0.5, 0.12), fonts);
  {
    Panel& p = *timeline;
    Stack col(Rect{0, 0, kDeskTimelineW, kDeskTimelineH}.inset(40.0), p.theme().gap);
    transport_row(p, col, play, prev_key, next_key, time);
    strip = &p.add<TimelineStrip>("strip", static_cast<int>(frames));
    strip->set_rect(col.rest());
  }
  views = std::make_unique<Panel>(kViewsPanelId, kDeskViewsW, kDeskViewsH, glm::dvec2(0.2, 0.26), fonts);
  {
    Panel& p = *views;
    Stack col(Rect{0, 0, kDeskViewsW, kDeskViewsH}.inset(40.0), p.theme().gap);
    add_visualizations(p, col, p.theme().row_height, true);
  }
  hud = std::make_unique<Panel>(kHudPanelId, kDeskHudW, kDeskHudH, glm::dvec2(0.4, 0.03), fonts);
  {
    Panel& p = *hud;
    const Rect inner = Rect{0, 0, kDeskHudW, kDeskHudH}.inset(24.0, 10.0);
    hud_line = &p.add<Label>("hud_line", "", Label::Role::Small, Align::Centre);
    hud_line->set_rect(split_rows(inner, 2, 0, 2.0));
    hud_message = &p.add<Label>("hud_message", "", Label::Role::Small, Align::Centre, true);
    hud_message->set_rect(split_rows(inner, 2, 1, 2.0));
  }
}

void EditorPanels::set_viewport(const DesktopViewport& v) {
  viewport_ = v;
  if (layout != PanelLayout::Desktop) return;
  const double s = desktop_ui_scale(v);
  const auto put = [&](ui::Panel& p, PanelPlacement& place, const ScreenRect& r) {
    glm::dvec2 size;
    const PanelPlacement want = desktop_placement(v, r, kDeskDistanceM, &size);
    if (place.anchor != Anchor::World) place = want;  // a locked timeline stays where it is
    p.set_size_m(size);
    p.set_render_scale(s);
  };
  put(*effect, effect_place, screen_rect(kEffectPanelId));
  put(*timeline, timeline_place, screen_rect(kTimelinePanelId));
  put(*views, views_place, screen_rect(kViewsPanelId));
  put(*hud, hud_place, screen_rect(kHudPanelId));
}

ScreenRect EditorPanels::screen_rect(std::string_view id) const {
  if (layout != PanelLayout::Desktop) return {};
  const DesktopViewport& v = viewport_;
  const double s = desktop_ui_scale(v);
  const auto px = [&](int layout_px) { return static_cast<int>(std::lround(layout_px * s)); };
  const int m = kDeskMargin;
  if (id == kEffectPanelId) return {m, m, px(kDeskEffectW), px(kDeskEffectH)};
  if (id == kTimelinePanelId)
    return {v.width - m - px(kDeskTimelineW), v.height - m - px(kDeskTimelineH), px(kDeskTimelineW), px(kDeskTimelineH)};
  if (id == kViewsPanelId) return {v.width - m - px(kDeskViewsW), m, px(kDeskViewsW), px(kDeskViewsH)};
  if (id == kHudPanelId) return {(v.width - px(kDeskHudW)) / 2, m, px(kDeskHudW), px(kDeskHudH)};
  return {};
}

void EditorPanels::show_effect(EffectType type) {
  for (std::size_t i = 0; i < effect_widgets.size(); ++i)
    effect_widgets[i]->set_rect(i == static_cast<std::size_t>(type) ? effect_widget_rect_ : ui::Rect{});
  menu->select(static_cast<int>(type));
}

std::vector<ui::Panel*> EditorPanels::all() {
  std::vector<ui::Panel*> out{effect.get(), timeline.get()};
  if (views) out.push_back(views.get());
  if (hud) out.push_back(hud.get());
  return out;
}

ui::Panel* EditorPanels::panel(std::string_view id) {
  for (ui::Panel* p : all())
    if (p->id() == id) return p;
  return nullptr;
}

ui::Panel* EditorPanels::panel_of(const ui::Widget* widget) {
  for (ui::Panel* p : all())
    for (const auto& w : p->widgets())
      if (w.get() == widget) return p;
  return nullptr;
}

void EditorPanels::place(const xr::InputState& input) {
  const auto put = [&](ui::Panel* p, const PanelPlacement& place) {
    if (p && place.anchor != Anchor::World) p->set_world_pose(anchor_pose(place.anchor, input) * place.offset);
  };
  put(effect.get(), effect_place);
  put(timeline.get(), timeline_place);
  put(views.get(), views_place);
  put(hud.get(), hud_place);
  plot->set_rect(show_tracks->on() ? plot_rect_ : ui::Rect{});
  minimap->set_rect(show_minimap->on() ? minimap_rect_ : ui::Rect{});
}

std::vector<ui::Panel*> EditorPanels::reachable_by(xr::Hand hand) {
  // On the desktop the mouse is the right hand's ray; the sim's left hand only has buttons.
  if (layout == PanelLayout::Desktop && hand == xr::Hand::Left) return {};
  const Anchor own = hand == xr::Hand::Left ? Anchor::LeftHand : Anchor::RightHand;
  std::vector<ui::Panel*> out;
  if (effect_place.anchor != own) out.push_back(effect.get());
  if (timeline_place.anchor != own) out.push_back(timeline.get());
  if (views) out.push_back(views.get());  // the HUD takes no input
  return out;
}

void EditorPanels::lock_timeline(bool locked) {
  if (locked) {
    timeline_place = PanelPlacement{Anchor::World, timeline->pose()};
  } else if (layout == PanelLayout::Hands) {
    timeline_place = {Anchor::RightHand, offset({-0.05, 0.12, -0.05}, -20.0)};
  } else {
    timeline_place.anchor = Anchor::Head;
    set_viewport(viewport_);
  }
  lock->set_on(locked);
}

}  // namespace vdfx::app
