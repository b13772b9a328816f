/// @file
/// @brief TrackMarker: a ring quad at the shown track's direction at the current frame.
#include "app/editor/track_marker.h"

#include <cmath>

namespace vdfx::app {

namespace {

// Laid out at the desktop panels' text scale (about 0.4 screen pixels per layout pixel at
// 1280 x 720 and 2 m, ui::Theme's small font then 13 px): a 110 px ring (0.16 m, 4.6 degrees)
// over the name, on a panel with no backdrop of its own so the subject shows through the ring.
constexpr int kW = 320, kRing = 110, kTagH = 52, kH = kRing + 8 + kTagH;
constexpr double kWidthM = 0.16 * kW / kRing;

/// The dark theme without the panel's backdrop and border (the tag draws its own).
const ui::Theme& marker_theme() {
  static const ui::Theme t = [] {
    ui::Theme m = ui::Theme::dark();
    m.panel_bg = ui::Rgba::hex(0x000000, 0.0f);
    m.panel_border = ui::Rgba::hex(0x000000, 0.0f);
    return m;
  }();
  return t;
}

/// The track's name in the small font on a dark pill as wide as the text.
class NameTag : public ui::Widget {
 public:
  explicit NameTag(std::string id) : Widget(std::move(id)) {}
  void set_text(std::string s) { set(text_, s); }
  bool interactive() const override { return false; }
  void draw(ui::DrawContext& ctx) const override {
    if (text_.empty()) return;
    const ui::Rect r = rect();
    const ui::Font& font = *ctx.fonts.regular;
    const double w = std::min(r.w, ctx.canvas.text_width(font, ctx.theme.font_small, text_) + 24.0);
    const ui::Rect pill{r.x + 0.5 * (r.w - w), r.y, w, r.h};
    ctx.canvas.fill_rounded_rect(pill, 0.5 * r.h, ui::Theme::dark().panel_bg);
    ctx.canvas.text(font, ctx.theme.font_small, text_, pill, ui::Align::Centre, ctx.theme.text);
  }

 private:
  std::string text_;
};

/// A ring around the panel's upper square: whole where the subject is seen, dashed where held.
class Ring : public ui::Widget {
 public:
  explicit Ring(std::string id) : Widget(std::move(id)) {}
  void set_held(bool held) { set(held_, held); }
  bool interactive() const override { return false; }
  void draw(ui::DrawContext& ctx) const override {
    const ui::Rect r = rect();
    const glm::dvec2 c{r.x + 0.5 * r.w, r.y + 0.5 * r.h};
    const double radius = 0.5 * std::min(r.w, r.h) - 6.0;
    if (!held_) {
      ctx.canvas.stroke_circle(c, radius, 9.0, ui::Theme::dark().panel_bg);  // seen on white too
      ctx.canvas.stroke_circle(c, radius, 5.0, ctx.theme.accent);
      ctx.canvas.fill_circle(c, 5.0, ctx.theme.accent);
      return;
    }
    constexpr int kDashes = 12;
    for (int i = 0; i < kDashes; ++i) {
      const double a0 = 2.0 * M_PI * i / kDashes, a1 = a0 + M_PI / kDashes;
      ctx.canvas.line(c + radius * glm::dvec2(std::cos(a0), std::sin(a0)),
                      c + radius * glm::dvec2(std::cos(a1), std::sin(a1)), 6.0,
                      ui::Rgba::hex(0xe0483c));
    }
  }

 private:
  bool held_ = false;
};

}  // namespace

TrackMarker::TrackMarker(std::shared_ptr<const ui::FontSet> fonts)
    : panel_(std::make_unique<ui::Panel>(kTrackMarkerPanelId, kW, kH,
                                         glm::dvec2(kWidthM, kWidthM * kH / kW), std::move(fonts),
                                         marker_theme())) {
  ring_ = &panel_->add<Ring>("track_ring");
  ring_->set_rect({0.5 * (kW - kRing), 0, kRing, kRing});
  name_ = &panel_->add<NameTag>("track_name");
  name_->set_rect({0, kRing + 8, kW, kTagH});
  panel_->set_visible(false);
}

void TrackMarker::set_head(const ui::Pose& head) {
  head_ = head;
  put();
}

void TrackMarker::show(const TrackView& v) {
  at_ = v.marker;
  panel_->set_visible(at_.has_value());
  static_cast<Ring*>(ring_)->set_held(v.marker_held);
  static_cast<NameTag*>(name_)->set_text(v.track);
  put();
}

void TrackMarker::put() {
  if (!at_) return;
  const Eigen::Vector3d u = effects::to_unit(*at_);
  const glm::dquat facing = math::look_rotation(at_->azimuth_deg, at_->altitude_deg);
  // The ring's centre, not the panel's, on the direction: the panel sits lower by the
  // distance between the two.
  constexpr double kRingAboveCentreM = (0.5 * kH - 0.5 * kRing) * kWidthM / kW;
  panel_->set_world_pose({head_.position + kDistanceM * glm::dvec3(u.x(), u.y(), u.z()) -
                              kRingAboveCentreM * (facing * glm::dvec3(0.0, 1.0, 0.0)),
                          facing});
}

}  // namespace vdfx::app
