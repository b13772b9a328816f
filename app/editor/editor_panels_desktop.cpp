/// @file
/// @brief EditorPanels' Desktop layout: panels on rectangles of the desktop view's window,
/// head-locked quads that cover them exactly, rendered at their on-screen resolution.
#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "app/editor/editor_panels.h"

namespace vdfx::app {

namespace {

// Desktop layout (layout pixels, drawn at desktop_ui_scale()).
constexpr int kDeskEffectW = 800, kDeskEffectH = 1600;
constexpr int kDeskTimelineW = 2310, kDeskTimelineH = 560;
constexpr int kDeskViewsW = 800, kDeskViewsH = 1140;
constexpr int kDeskHudW = 1500, kDeskHudH = 110;
constexpr int kDeskRenameW = RenameKeyboard::kWidth, kDeskRenameH = RenameKeyboard::kHeight;
constexpr int kDeskMargin = 12;         //!< screen pixels between panels and the window edge
constexpr double kDeskDistanceM = 1.0;  //!< head-locked quads at this depth
/// Layout pixels the Desktop layout needs across and down the window at scale 1.
constexpr double kDeskLayoutW = 3200.0, kDeskLayoutH = 1800.0;

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
    *size_m = {(tan_x(r.x + r.w) - tan_x(r.x)) * distance_m,
               (tan_y(r.y) - tan_y(r.y + r.h)) * distance_m};
  return {Anchor::Head,
          xr::Pose{{cx * distance_m, cy * distance_m, -distance_m}, {1.0, 0.0, 0.0, 0.0}}};
}

void EditorPanels::build_desktop_panels(std::shared_ptr<const ui::FontSet> fonts,
                                        std::int64_t frames) {
  using namespace ui;
  build_effect_panel(fonts, kDeskEffectW, kDeskEffectH, glm::dvec2(0.2, 0.4));
  timeline_ = std::make_unique<Panel>(kTimelinePanelId, kDeskTimelineW, kDeskTimelineH,
                                      glm::dvec2(0.5, 0.12), fonts);
  {
    Panel& p = *timeline_;
    Stack col(Rect{0, 0, kDeskTimelineW, kDeskTimelineH}.inset(40.0), p.theme().gap);
    add_transport_row(p, col);
    strip_ = &p.add<TimelineStrip>("strip", static_cast<int>(frames));
    strip_->set_rect(col.rest());
  }
  views_ = std::make_unique<Panel>(kViewsPanelId, kDeskViewsW, kDeskViewsH, glm::dvec2(0.2, 0.26),
                                   fonts);
  {
    Panel& p = *views_;
    Stack col(Rect{0, 0, kDeskViewsW, kDeskViewsH}.inset(40.0), p.theme().gap);
    track_.build(p, col, true);
    add_visualizations(p, col, p.theme().row_height, true);
  }
  hud_ = std::make_unique<Panel>(kHudPanelId, kDeskHudW, kDeskHudH, glm::dvec2(0.4, 0.03), fonts);
  {
    Panel& p = *hud_;
    const Rect inner = Rect{0, 0, kDeskHudW, kDeskHudH}.inset(24.0, 10.0);
    hud_line_ = &p.add<Label>("hud_line", "", Label::Role::Small, Align::Centre);
    hud_line_->set_rect(split_rows(inner, 2, 0, 2.0));
    hud_message_ = &p.add<Label>("hud_message", "", Label::Role::Small, Align::Centre, true);
    hud_message_->set_rect(split_rows(inner, 2, 1, 2.0));
  }
}

void EditorPanels::set_viewport(const DesktopViewport& v) {
  viewport_ = v;
  if (layout_ != PanelLayout::Desktop) return;
  const double s = desktop_ui_scale(v);
  const auto put = [&](ui::Panel& p, PanelPlacement& place, const ScreenRect& r) {
    glm::dvec2 size;
    const PanelPlacement want = desktop_placement(v, r, kDeskDistanceM, &size);
    if (place.anchor != Anchor::World) place = want;  // a locked timeline stays where it is
    p.set_size_m(size);
    p.set_render_scale(s);
  };
  put(*effect_, effect_place_, screen_rect(kEffectPanelId));
  put(*timeline_, timeline_place_, screen_rect(kTimelinePanelId));
  put(*views_, views_place_, screen_rect(kViewsPanelId));
  put(*hud_, hud_place_, screen_rect(kHudPanelId));
  put(keyboard_->panel(), keyboard_place_, screen_rect(kRenamePanelId));
}

ScreenRect EditorPanels::screen_rect(std::string_view id) const {
  if (layout_ != PanelLayout::Desktop) return {};
  const DesktopViewport& v = viewport_;
  const double s = desktop_ui_scale(v);
  const auto px = [&](int layout_px) { return static_cast<int>(std::lround(layout_px * s)); };
  const int m = kDeskMargin;
  if (id == kEffectPanelId) return {m, m, px(kDeskEffectW), px(kDeskEffectH)};
  if (id == kTimelinePanelId)
    return {v.width - m - px(kDeskTimelineW), v.height - m - px(kDeskTimelineH), px(kDeskTimelineW),
            px(kDeskTimelineH)};
  if (id == kViewsPanelId)
    return {v.width - m - px(kDeskViewsW), m, px(kDeskViewsW), px(kDeskViewsH)};
  if (id == kHudPanelId) return {(v.width - px(kDeskHudW)) / 2, m, px(kDeskHudW), px(kDeskHudH)};
  if (id == kRenamePanelId)  // over the view, just above the timeline
    return {(v.width - px(kDeskRenameW)) / 2,
            v.height - 2 * m - px(kDeskTimelineH) - px(kDeskRenameH), px(kDeskRenameW),
            px(kDeskRenameH)};
  return {};
}

}  // namespace vdfx::app
