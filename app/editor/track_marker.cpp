/// @file
/// @brief TrackMarker: a ring quad at the shown track's direction at the current frame.
#include "app/editor/track_marker.h"

#include <cmath>

namespace vdfx::app {

namespace {

constexpr int kW = 240, kH = 300;

/// A ring around the panel's upper square: whole where the subject is seen, dashed where held.
class Ring : public ui::Widget {
 public:
  explicit Ring(std::string id) : Widget(std::move(id)) {}
  void set_held(bool held) { set(held_, held); }
  bool interactive() const override { return false; }
  void draw(ui::DrawContext& ctx) const override {
    const ui::Rect r = rect();
    const glm::dvec2 c{r.x + 0.5 * r.w, r.y + 0.5 * r.h};
    const double radius = 0.5 * std::min(r.w, r.h) - 10.0;
    if (!held_) {
      ctx.canvas.stroke_circle(c, radius, 10.0, ctx.theme.accent);
      ctx.canvas.fill_circle(c, 8.0, ctx.theme.accent);
      return;
    }
    constexpr int kDashes = 12;
    for (int i = 0; i < kDashes; ++i) {
      const double a0 = 2.0 * M_PI * i / kDashes, a1 = a0 + M_PI / kDashes;
      ctx.canvas.line(c + radius * glm::dvec2(std::cos(a0), std::sin(a0)),
                      c + radius * glm::dvec2(std::cos(a1), std::sin(a1)), 10.0,
                      ui::Rgba::hex(0xe0483c));
    }
  }

 private:
  bool held_ = false;
};

}  // namespace

TrackMarker::TrackMarker(std::shared_ptr<const ui::FontSet> fonts)
    : panel_(std::make_unique<ui::Panel>(kTrackMarkerPanelId, kW, kH,
                                         glm::dvec2(0.16, 0.16 * kH / kW), std::move(fonts))) {
  ring_ = &panel_->add<Ring>("track_ring");
  ring_->set_rect({10, 10, kW - 20, kW - 20});
  name_ = &panel_->add<ui::Label>("track_name", "", ui::Label::Role::Small, ui::Align::Centre);
  name_->set_rect({0, kW - 10, kW, kH - kW});
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
  name_->set_text(v.track);
  put();
}

void TrackMarker::put() {
  if (!at_) return;
  const Eigen::Vector3d u = effects::to_unit(*at_);
  panel_->set_world_pose({head_.position + kDistanceM * glm::dvec3(u.x(), u.y(), u.z()),
                          math::look_rotation(at_->azimuth_deg, at_->altitude_deg)});
}

}  // namespace vdfx::app
