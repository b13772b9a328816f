/// @file
/// @brief EditorPanels: building and placing the editor's panels in both layouts.
#include "app/editor/editor_panels.h"

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
constexpr int kEffectW = 1000, kEffectH = 1600;
constexpr int kTimelineW = 2000, kTimelineH = 1200;

// The option rows under the effect widget (flare: style and light; grain: a 2 x 2 style grid).
constexpr double kMenuInset = 16.0;  // a MenuList's frame around its rows

std::string grain_style_title(effects::GrainStyle s) {
  switch (s) {
    case effects::GrainStyle::Headset: return "Headset";
    case effects::GrainStyle::Surface: return "Surface";
    case effects::GrainStyle::ObjectCloud: return "Object cloud";
    case effects::GrainStyle::FreeCloud: return "Free cloud";
  }
  return {};
}

}  // namespace

std::string effect_widget_id(EditTarget target) {
  return std::string(target.name());
}

EditorPanels::EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count,
                           PanelLayout layout_, DesktopViewport viewport)
    : layout(layout_), viewport_(viewport) {
  if (layout == PanelLayout::Hands) {
    build_effect_panel(fonts, kEffectW, kEffectH, glm::dvec2(0.25, 0.25 * kEffectH / kEffectW));
    build_hands_timeline(fonts, frame_count);
    effect_place = {Anchor::LeftHand, offset({0.05, 0.16, -0.05}, -20.0)};
    timeline_place = {Anchor::RightHand, offset({-0.05, 0.12, -0.05}, -20.0)};
  } else {
    build_desktop_panels(fonts, frame_count);
    set_viewport(viewport);
  }
  show_effect(EditTarget(EffectType::Exposure));
}

void EditorPanels::build_effect_panel(std::shared_ptr<const ui::FontSet> fonts, int width,
                                      int height, glm::dvec2 size_m) {
  using namespace ui;
  effect = std::make_unique<Panel>(kEffectPanelId, width, height, size_m, fonts);
  Panel& p = *effect;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, static_cast<double>(width), static_cast<double>(height)}.inset(40.0), t.gap);
  title = &p.add<Label>("title", "Effects", Label::Role::Title);
  title->set_rect(col.next(64));
  std::vector<std::string> names;
  for (const EditTarget target : all_edit_targets()) names.push_back(target.title());
  menu = &p.add<MenuList>("effect_menu", names, static_cast<int>(EffectType::Exposure),
                          t.row_height, 2);
  menu->set_rect(col.next(menu->rows() * t.row_height + kMenuInset));
  effect_widget_rect_ = col.next(330);
  options_rect_ = col.next(2 * t.row_height + kMenuInset + t.gap);
  blur = &p.add<Slider1D>("blur", "Blur", Axis{0.0, 10.0, 0.1, "%.1f", "\u00b0", ""}, 0.0, 0.0);
  tint = &p.add<ColourWheel>("tint", "Tint");
  exposure = &p.add<Slider1D>("exposure", "Exposure", Axis{-8.0, 8.0, 0.1, "%+.1f", " stops", ""},
                              0.0, 0.0);
  saturation =
      &p.add<Slider1D>("saturation", "Saturation", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 1.0, 1.0);
  contrast =
      &p.add<Slider1D>("contrast", "Contrast", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 1.0, 1.0);
  vignette =
      &p.add<Pad2D>("vignette", "Vignette", Axis{0.0, 180.0, 1.0, "%.0f", "\u00b0", "radius"},
                    Axis{0.01, 180.0, 1.0, "%.0f", "\u00b0", "falloff"}, glm::dvec2(180.0, 0.01));
  flare_intensity =
      &p.add<Slider1D>("flare", "Flare intensity", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 0.0, 0.0);
  flare_style =
      &p.add<MenuList>("flare_style", std::vector<std::string>{"Headset", "Directional"},
                       static_cast<int>(effects::FlareStyle::Directional), t.row_height, 2);
  set_light = &p.add<Button>("set_light", "Set light here");
  auto_light = &p.add<Toggle>("auto_light", "Auto light", true);
  grain_intensity =
      &p.add<Slider1D>("grain", "Grain intensity", Axis{0.0, 1.0, 0.01, "%.2f", "", ""}, 0.0, 0.0);
  Axis size_axis{0.25, 4.0, 0.0, "%.2f", "\u00d7", ""};
  size_axis.log = true;
  grain_size = &p.add<Slider1D>("grain_size", "Grain size", size_axis, 1.0, 1.0);
  std::vector<std::string> styles;
  for (const auto st : effects::kGrainStyles) styles.push_back(grain_style_title(st));
  grain_style = &p.add<MenuList>("grain_style", styles, 0, t.row_height, 2);
  effect_widgets = {blur,     tint,     exposure,        saturation,
                    contrast, vignette, flare_intensity, grain_intensity};
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
  exponent = &p.add<Slider1D>("exponent", "Exponent \u03b1", Axis{0.1, 3.9, 0.1, "%.1f", "", ""},
                              1.0, 1.0);
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

void EditorPanels::add_visualizations(ui::Panel& p, ui::Stack& col, double toggles_h,
                                      bool stacked) {
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
    plot_rect_ = {rest.x, minimap_rect_.bottom() + t.gap, rest.w,
                  rest.bottom() - minimap_rect_.bottom() - t.gap};
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

/// The top row of the timeline: play, previous / next keyframe, the time label.
void EditorPanels::add_transport_row(ui::Panel& p, ui::Stack& col) {
  using namespace ui;
  const Theme& t = p.theme();
  Stack top(col.next(t.row_height), t.gap, Stack::Axis::Horizontal);
  play = &p.add<Button>("play", "", Icon::Play);
  play->set_rect(top.next(120));
  prev_key = &p.add<Button>("prev_key", "\u2190 Key");
  prev_key->set_rect(top.next(220));
  next_key = &p.add<Button>("next_key", "Key \u2192");
  next_key->set_rect(top.next(220));
  time = &p.add<Label>("time", "", Label::Role::Body, Align::Right, true);
  time->set_rect(top.rest());
}

void EditorPanels::build_hands_timeline(std::shared_ptr<const ui::FontSet> fonts,
                                        std::int64_t frames) {
  using namespace ui;
  timeline = std::make_unique<Panel>(kTimelinePanelId, kTimelineW, kTimelineH, glm::dvec2(0.5, 0.3),
                                     fonts);
  Panel& p = *timeline;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, kTimelineW, kTimelineH}.inset(40.0), t.gap);
  add_transport_row(p, col);
  strip = &p.add<TimelineStrip>("strip", static_cast<int>(frames));
  strip->set_rect(col.next(220));
  add_visualizations(p, col, t.row_height, false);
}

void EditorPanels::show_values(EditTarget target, std::span<const double> v) {
  const auto put = [](ui::Slider1D* slider, double value) {
    if (!slider->pressed()) slider->set_value(value);  // it shows its own value while dragged
  };
  if (target.is_flare()) return put(flare_intensity, v[0]);
  if (target.is_grain()) {
    put(grain_intensity, v[0]);
    put(grain_size, v[1]);
    return;
  }
  if (effect_widgets[static_cast<std::size_t>(target.index())]->pressed()) return;
  switch (*target.stack_effect()) {
    case EffectType::Tint: {
      const glm::dvec2 hs = ui::hue_sat_from_tint_gain({v[0], v[1], v[2]});
      if (glm::length(hs - glm::dvec2(tint->hue(), tint->sat())) > 1e-6)
        tint->set_hue_sat(hs.x, hs.y);
      break;
    }
    case EffectType::Vignette: vignette->set_value({v[0], v[1]}); break;
    case EffectType::Blur: blur->set_value(v[0]); break;
    case EffectType::Exposure: exposure->set_value(v[0]); break;
    case EffectType::Saturation: saturation->set_value(v[0]); break;
    case EffectType::Contrast: contrast->set_value(v[0]); break;
  }
}

bool EditorPanels::edits_values(EditTarget target, const ui::Widget* w) const {
  return w == effect_widgets[static_cast<std::size_t>(target.index())] ||
         (target.is_grain() && w == grain_size);
}

std::vector<double> EditorPanels::values_of(EditTarget target, const ui::Event& e,
                                            std::span<const double> current) const {
  if (target == EffectType::Tint) {
    const Eigen::Vector3d g = ui::tint_gain_from_hue_sat(e.new_value.x, e.new_value.y);
    return {g[0], g[1], g[2]};
  }
  if (target == EffectType::Vignette) return {e.new_value.x, e.new_value.y};
  if (target.is_grain()) {
    std::vector<double> v(current.begin(), current.end());
    v[e.source == grain_size ? 1 : 0] = e.new_value.x;
    return v;
  }
  return {e.new_value.x};
}

void EditorPanels::show_options(const effects::FlareEffect& flare,
                                const effects::GrainEffect& grain) {
  flare_style->select(static_cast<int>(flare.style));
  auto_light->set_on(std::holds_alternative<effects::AutoLight>(flare.light));
  const auto it =
      std::find(effects::kGrainStyles.begin(), effects::kGrainStyles.end(), grain.style);
  grain_style->select(static_cast<int>(it - effects::kGrainStyles.begin()));
}

void EditorPanels::show_effect(EditTarget target) {
  const ui::Theme& t = effect->theme();
  for (std::size_t i = 0; i < effect_widgets.size(); ++i)
    effect_widgets[i]->set_rect(static_cast<int>(i) == target.index() ? effect_widget_rect_
                                                                      : ui::Rect{});
  for (ui::Widget* w : std::initializer_list<ui::Widget*>{grain_size, flare_style, set_light,
                                                          auto_light, grain_style})
    w->set_rect({});
  if (target.is_grain()) {
    grain_intensity->set_rect(ui::split_rows(effect_widget_rect_, 2, 0, t.gap));
    grain_size->set_rect(ui::split_rows(effect_widget_rect_, 2, 1, t.gap));
    grain_style->set_rect(
        {options_rect_.x, options_rect_.y, options_rect_.w, 2 * t.row_height + kMenuInset});
  }
  if (target.is_flare()) {
    ui::Stack rows(options_rect_, t.gap);
    flare_style->set_rect(rows.next(t.row_height + kMenuInset));
    const ui::Rect light = rows.next(t.row_height);
    set_light->set_rect(ui::split_cols(light, 2, 0, t.gap));
    auto_light->set_rect(ui::split_cols(light, 2, 1, t.gap));
  }
  menu->select(target.index());
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
    if (p && place.anchor != Anchor::World)
      p->set_world_pose(anchor_pose(place.anchor, input) * place.offset);
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
