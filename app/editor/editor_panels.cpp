/// @file
/// @brief EditorPanels: building the editor's panels in both layouts.
#include "app/editor/editor_panels.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "app/editor/suggest_worker.h"

namespace vdfx::app {

using effects::EffectType;

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

EditorPanels::EditorPanels(std::shared_ptr<const ui::FontSet> fonts, std::int64_t frame_count,
                           PanelLayout layout, DesktopViewport viewport)
    : layout_(layout),
      marker_(std::make_unique<TrackMarker>(fonts)),
      keyboard_(std::make_unique<RenameKeyboard>(fonts)),
      viewport_(viewport) {
  if (layout_ == PanelLayout::Hands) {
    build_effect_panel(fonts, kEffectW, kEffectH, glm::dvec2(0.25, 0.25 * kEffectH / kEffectW));
    build_hands_timeline(fonts, frame_count);
    effect_place_ = {Anchor::LeftHand, offset({0.05, 0.16, -0.05}, -20.0)};
    timeline_place_ = {Anchor::RightHand, offset({-0.05, 0.12, -0.05}, -20.0)};
    keyboard_offset_ = offset({0.0, -0.12, -0.6}, 10.0);  // ahead, below the eyes
    keyboard_place_ = {Anchor::Head, keyboard_offset_};
  } else {
    build_desktop_panels(fonts, frame_count);
    set_viewport(viewport);
  }
  show_effect(EditTarget(EffectType::Exposure));
}

void EditorPanels::build_effect_panel(std::shared_ptr<const ui::FontSet> fonts, int width,
                                      int height, glm::dvec2 size_m) {
  using namespace ui;
  effect_ = std::make_unique<Panel>(kEffectPanelId, width, height, size_m, fonts);
  Panel& p = *effect_;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, static_cast<double>(width), static_cast<double>(height)}.inset(40.0), t.gap);
  title_ = &p.add<Label>("title", "Effects", Label::Role::Title);
  title_->set_rect(col.next(64));
  std::vector<std::string> names;
  for (const EditTarget target : all_edit_targets()) names.push_back(target.title());
  menu_ = &p.add<MenuList>("effect_menu", names, static_cast<int>(EffectType::Exposure),
                           t.row_height, 2);
  menu_->set_rect(col.next(menu_->rows() * t.row_height + kMenuInset));
  effect_widget_rect_ = col.next(330);
  options_rect_ = col.next(2 * t.row_height + kMenuInset + t.gap);
  blur_ = &p.add<Slider1D>("blur", "Blur", Axis{0.0, 10.0, 0.1, "%.1f", "\u00b0", ""}, 0.0, 0.0);
  tint_ = &p.add<ColourWheel>("tint", "Tint");
  exposure_ = &p.add<Slider1D>("exposure", "Exposure", Axis{-8.0, 8.0, 0.1, "%+.1f", " stops", ""},
                               0.0, 0.0);
  saturation_ =
      &p.add<Slider1D>("saturation", "Saturation", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 1.0, 1.0);
  contrast_ =
      &p.add<Slider1D>("contrast", "Contrast", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 1.0, 1.0);
  vignette_ =
      &p.add<Pad2D>("vignette", "Vignette", Axis{0.0, 180.0, 1.0, "%.0f", "\u00b0", "radius"},
                    Axis{0.01, 180.0, 1.0, "%.0f", "\u00b0", "falloff"}, glm::dvec2(180.0, 0.01));
  flare_intensity_ =
      &p.add<Slider1D>("flare", "Flare intensity", Axis{0.0, 4.0, 0.05, "%.2f", "", ""}, 0.0, 0.0);
  flare_style_ =
      &p.add<MenuList>("flare_style", std::vector<std::string>{"Headset", "Directional"},
                       static_cast<int>(effects::FlareStyle::Directional), t.row_height, 2);
  set_light_ = &p.add<Button>("set_light", "Set light here");
  auto_light_ = &p.add<Toggle>("auto_light", "Auto light", true);
  grain_intensity_ =
      &p.add<Slider1D>("grain", "Grain intensity", Axis{0.0, 1.0, 0.01, "%.2f", "", ""}, 0.0, 0.0);
  Axis size_axis{0.25, 4.0, 0.0, "%.2f", "\u00d7", ""};
  size_axis.log = true;
  grain_size_ = &p.add<Slider1D>("grain_size", "Grain size", size_axis, 1.0, 1.0);
  std::vector<std::string> styles;
  for (const auto st : effects::kGrainStyles) styles.push_back(grain_style_title(st));
  grain_style_ = &p.add<MenuList>("grain_style", styles, 0, t.row_height, 2);
  suggest_strength_ = &p.add<Slider1D>("suggest_strength", "Strength",
                                       Axis{0.0, 100.0, 5.0, "%.0f", " %", ""}, 100.0, 0.0);
  suggest_ = &p.add<Button>("suggest", "Suggest");
  effect_widgets_ = {blur_,     tint_,     exposure_,        saturation_,
                     contrast_, vignette_, flare_intensity_, grain_intensity_};
  const Rect row = col.next(t.row_height);
  undo_ = &p.add<Button>("undo", "\u2190 Undo");
  undo_->set_rect(split_cols(row, 2, 0, t.gap));
  redo_ = &p.add<Button>("redo", "Redo \u2192");
  redo_->set_rect(split_cols(row, 2, 1, t.gap));
  const Rect keys = col.next(t.row_height);
  delete_nearest_ = &p.add<Button>("delete_nearest", "Delete nearest");
  delete_nearest_->set_rect(split_cols(keys, 2, 0, t.gap));
  deselect_ = &p.add<Button>("deselect", "Deselect");
  deselect_->set_rect(split_cols(keys, 2, 1, t.gap));
  deselect_->set_enabled(false);
  exponent_ = &p.add<Slider1D>("exponent", "Exponent \u03b1", Axis{0.1, 3.9, 0.1, "%.1f", "", ""},
                               1.0, 1.0);
  exponent_->set_rect(col.next(130));
  // In an author's unit: how many degrees of view one second of video weighs like
  // (docs/interpolation.md, "Time"), on a logarithmic track.
  Axis time_axis{0.1, 2000.0, 0.0, "%.2g", "\u00b0 of view", ""};
  time_axis.log = true;
  time_scale_ = &p.add<Slider1D>("time_scale", "1 s of video weighs like", time_axis,
                                 effects::kAuthorDegPerSecond, effects::kAuthorDegPerSecond);
  time_scale_->set_rect(col.next(130));
  status_ = &p.add<Label>("status", "", Label::Role::Small, Align::Left, true);
  status_->set_rect(col.next(60));
}

void EditorPanels::add_visualizations(ui::Panel& p, ui::Stack& col, double toggles_h,
                                      bool stacked) {
  using namespace ui;
  const Theme& t = p.theme();
  if (stacked) {  // Desktop: two rows of toggles, then the minimap over the plot
    const Rect row = col.next(toggles_h);
    show_tracks_ = &p.add<Toggle>("show_tracks", "Track plot", true);
    show_tracks_->set_rect(split_cols(row, 2, 0, t.gap));
    show_minimap_ = &p.add<Toggle>("show_minimap", "Minimap", true);
    show_minimap_->set_rect(split_cols(row, 2, 1, t.gap));
    lock_ = &p.add<Toggle>("lock", "Lock timeline in world", false);
    lock_->set_rect(col.next(toggles_h));
    const Rect rest = col.rest();
    // The map keeps its 2:1 (ui/minimap.cpp); the plot below keeps room for its curve.
    constexpr double kPlotMinH = 200.0;
    minimap_rect_ = {rest.x, rest.y, rest.w,
                     std::min(0.5 * rest.w + 90.0, rest.h - kPlotMinH - t.gap)};
    plot_rect_ = {rest.x, minimap_rect_.bottom() + t.gap, rest.w,
                  rest.bottom() - minimap_rect_.bottom() - t.gap};
  } else {  // Hands: toggles in one row, the hint, then the plot beside the minimap
    Stack toggles(col.next(toggles_h), t.gap, Stack::Axis::Horizontal);
    show_tracks_ = &p.add<Toggle>("show_tracks", "Track plot", true);
    show_tracks_->set_rect(toggles.next(560));
    show_minimap_ = &p.add<Toggle>("show_minimap", "Minimap", true);
    show_minimap_->set_rect(toggles.next(520));
    lock_ = &p.add<Toggle>("lock", "Lock in world", false);
    lock_->set_rect(toggles.rest());
    hint_ = &p.add<Label>("hint", "", Label::Role::Small, Align::Left, true);
    hint_->set_rect(col.next(56));
    const Rect bottom = col.rest();
    plot_rect_ = {bottom.x, bottom.y, 1000, bottom.h};
    minimap_rect_ = {bottom.x + 1000 + t.gap, bottom.y, bottom.w - 1000 - t.gap, bottom.h};
  }
  plot_ = &p.add<Plot>("track_plot", "Value over time at the view", 0.0, 1.0, "%.1f");
  plot_->set_rect(plot_rect_);
  minimap_ = &p.add<Minimap>("minimap", "Value over the sphere");
  minimap_->set_rect(minimap_rect_);
}

/// The top row of the timeline: play, previous / next keyframe, the time label.
void EditorPanels::add_transport_row(ui::Panel& p, ui::Stack& col) {
  using namespace ui;
  const Theme& t = p.theme();
  Stack top(col.next(t.row_height), t.gap, Stack::Axis::Horizontal);
  play_ = &p.add<Button>("play", "", Icon::Play);
  play_->set_rect(top.next(120));
  prev_key_ = &p.add<Button>("prev_key", "\u2190 Key");
  prev_key_->set_rect(top.next(220));
  next_key_ = &p.add<Button>("next_key", "Key \u2192");
  next_key_->set_rect(top.next(220));
  time_ = &p.add<Label>("time", "", Label::Role::Body, Align::Right, true);
  time_->set_rect(top.rest());
}

void EditorPanels::build_hands_timeline(std::shared_ptr<const ui::FontSet> fonts,
                                        std::int64_t frames) {
  using namespace ui;
  timeline_ = std::make_unique<Panel>(kTimelinePanelId, kTimelineW, kTimelineH,
                                      glm::dvec2(0.5, 0.3), fonts);
  Panel& p = *timeline_;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, kTimelineW, kTimelineH}.inset(40.0), t.gap);
  add_transport_row(p, col);
  strip_ = &p.add<TimelineStrip>("strip", static_cast<int>(frames));
  strip_->set_rect(col.next(220));
  track_.build(p, col, false);
  add_visualizations(p, col, t.row_height, false);
}

PanelControl EditorPanels::control_of(const ui::Widget* w, EditTarget target) const {
  if (!w) return PanelControl::None;
  if (const PanelControl c = track_.control_of(w); c != PanelControl::None) return c;
  if (const PanelControl c = keyboard_->control_of(w); c != PanelControl::None) return c;
  if (w == effect_widgets_[static_cast<std::size_t>(target.index())] ||
      (target.is_grain() && w == grain_size_))
    return PanelControl::EffectValues;
  const std::pair<const ui::Widget*, PanelControl> table[] = {
      {menu_, PanelControl::EffectMenu},
      {exponent_, PanelControl::Exponent},
      {time_scale_, PanelControl::TimeScale},
      {flare_style_, PanelControl::FlareStyle},
      {set_light_, PanelControl::SetLight},
      {auto_light_, PanelControl::AutoLight},
      {grain_style_, PanelControl::GrainStyle},
      {undo_, PanelControl::Undo},
      {redo_, PanelControl::Redo},
      {delete_nearest_, PanelControl::Delete},
      {deselect_, PanelControl::Deselect},
      {minimap_, PanelControl::Minimap},
      {play_, PanelControl::Play},
      {prev_key_, PanelControl::PreviousKey},
      {next_key_, PanelControl::NextKey},
      {strip_, PanelControl::Strip},
      {show_tracks_, PanelControl::ShowTrackPlot},
      {show_minimap_, PanelControl::ShowMinimap},
      {lock_, PanelControl::LockTimeline},
      {suggest_, PanelControl::Suggest},
      {suggest_strength_, PanelControl::SuggestStrength},
  };
  for (const auto& [widget, control] : table)
    if (w == widget) return control;
  return PanelControl::None;
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
    v[e.source == grain_size_ ? 1 : 0] = e.new_value.x;
    return v;
  }
  return {e.new_value.x};
}

void EditorPanels::show_effect(EditTarget target) {
  const ui::Theme& t = effect_->theme();
  for (std::size_t i = 0; i < effect_widgets_.size(); ++i)
    effect_widgets_[i]->set_rect(static_cast<int>(i) == target.index() ? effect_widget_rect_
                                                                       : ui::Rect{});
  for (ui::Widget* w :
       std::initializer_list<ui::Widget*>{grain_size_, flare_style_, set_light_, auto_light_,
                                          grain_style_, suggest_strength_, suggest_})
    w->set_rect({});
  if (suggestion_for(target)) {  // the strength slider, "Suggest ..." beside its track
    const ui::Rect& o = options_rect_;
    const double slider_w = std::round(0.45 * o.w), h = 130.0;
    suggest_strength_->set_rect({o.x, o.y, slider_w, h});
    suggest_->set_rect(
        {o.x + slider_w + t.gap, o.y + h - t.row_height, o.w - slider_w - t.gap, t.row_height});
  }
  if (target.is_grain()) {
    grain_intensity_->set_rect(ui::split_rows(effect_widget_rect_, 2, 0, t.gap));
    grain_size_->set_rect(ui::split_rows(effect_widget_rect_, 2, 1, t.gap));
    grain_style_->set_rect(
        {options_rect_.x, options_rect_.y, options_rect_.w, 2 * t.row_height + kMenuInset});
  }
  if (target.is_flare()) {
    ui::Stack rows(options_rect_, t.gap);
    flare_style_->set_rect(rows.next(t.row_height + kMenuInset));
    const ui::Rect light = rows.next(t.row_height);
    set_light_->set_rect(ui::split_cols(light, 2, 0, t.gap));
    auto_light_->set_rect(ui::split_cols(light, 2, 1, t.gap));
  }
  menu_->select(target.index());
}

void EditorPanels::lock_timeline(bool locked) {
  if (locked) {
    timeline_place_ = PanelPlacement{Anchor::World, timeline_->pose()};
  } else if (layout_ == PanelLayout::Hands) {
    timeline_place_ = {Anchor::RightHand, offset({-0.05, 0.12, -0.05}, -20.0)};
  } else {
    timeline_place_.anchor = Anchor::Head;
    set_viewport(viewport_);
  }
}

}  // namespace vdfx::app
