/// @file
/// @brief Ray hit testing and the Pointer state machine.
#include "ui/interaction.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace vdfx::ui {

std::optional<PlaneHit> intersect_panel_plane(const Panel& panel, const Ray& ray) {
  const glm::dvec3 n = panel.normal();
  const double denom = glm::dot(ray.direction, n);
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double t = glm::dot(panel.pose().position - ray.origin, n) / denom;
  if (!(t > 0.0)) return std::nullopt;
  const glm::dvec3 local = panel.pose().inverse().transform(ray.origin + t * ray.direction);
  PlaneHit h;
  h.pixel = panel.pixel_of_local({local.x, local.y});
  h.distance = t;
  h.front = denom < 0.0;  // travelling against the normal: coming from the side it faces
  const glm::dvec2 half = 0.5 * panel.size_m();
  h.inside = std::abs(local.x) <= half.x && std::abs(local.y) <= half.y;
  return h;
}

std::optional<PanelHit> hit_panels(std::span<Panel* const> panels, const Ray& ray) {
  std::optional<PanelHit> best;
  for (Panel* p : panels) {
    if (!p || !p->visible()) continue;
    const auto h = intersect_panel_plane(*p, ray);
    if (!h || !h->front || !h->inside) continue;
    if (!best || h->distance < best->distance) best = PanelHit{p, h->pixel, h->distance};
  }
  return best;
}

struct Pointer::Frame {
  std::span<Panel* const> panels;
  const PointerInput& in;
  double dt;
  std::vector<Event> events;

  void emit(const Ref& r, EventKind k, glm::dvec2 o, glm::dvec2 n) {
    events.push_back({r.panel->id(), r.widget->id(), k, o, n, in_reach(panels, r)});
  }
  /// Runs a change on a widget and reports ValueChanged if its value moved.
  template <class Fn>
  void change(const Ref& r, Widget& w, Fn&& fn) {
    const glm::dvec2 before = w.value();
    fn();
    if (w.value() != before) emit(r, EventKind::ValueChanged, before, w.value());
  }
};

Widget* Pointer::in_reach(std::span<Panel* const> panels, const Ref& r) {
  if (r.empty()) return nullptr;
  for (Panel* p : panels)
    if (p == r.panel) return r.widget;
  return nullptr;
}

void Pointer::clear_focus() {
  if (focus_.widget) focus_.widget->set_focused(false);
  focus_ = {};
  stick_active_ = false;
}

std::vector<Event> Pointer::update(std::span<Panel* const> panels, const PointerInput& in,
                                   double dt) {
  Frame f{panels, in, dt, {}};
  hover(f);
  press(f);
  drag(f);
  release(f);
  stick(f);
  return std::move(f.events);
}

/// Hit test and hover.
void Pointer::hover(Frame& f) {
  hit_ = hit_panels(f.panels, f.in.ray);
  Ref now;
  if (hit_) {
    if (Widget* w = hit_->panel->widget_at(hit_->pixel)) now = {hit_->panel, w};
  }
  if (!(now == hover_)) {
    if (Widget* w = in_reach(f.panels, hover_)) w->set_hovered(false);
    hover_ = now;
  }
  if (Widget* w = in_reach(f.panels, hover_)) {
    w->set_hovered(true);
    w->hover_at(hit_->pixel);
  }
}

/// Press: focus moves to the pressed widget; draggable widgets start following the ray.
void Pointer::press(Frame& f) {
  if (!f.in.trigger.pressed || hover_.empty()) return;
  press_ = hover_;
  Widget* w = press_.widget;
  w->set_pressed(true);
  if (w->focusable() && !(focus_ == press_)) {
    if (Widget* old = in_reach(f.panels, focus_)) old->set_focused(false);
    focus_ = press_;
    stick_active_ = false;
    w->set_focused(true);
  }
  if (!w->draggable()) return;
  drag_start_value_ = w->value();
  f.emit(press_, EventKind::DragBegin, drag_start_value_, drag_start_value_);
  fine_ = f.in.fine;
  drag_anchor_ = hit_->pixel;
  // A fine press keeps the value where it is (the motion from here moves it); a plain press
  // jumps it under the pointer.
  drag_to_ = fine_ ? w->drag_point().value_or(hit_->pixel) : hit_->pixel;
  drag_offset_ = drag_to_ - hit_->pixel;
  if (!fine_) f.change(press_, *w, [&] { w->drag_to(hit_->pixel); });
}

/// Held: follow the ray on the pressed widget's panel plane, even past its edges.
void Pointer::drag(Frame& f) {
  Widget* held = in_reach(f.panels, press_);
  if (!f.in.trigger.down || f.in.trigger.pressed || !held || !held->draggable()) return;
  const auto h = intersect_panel_plane(*press_.panel, f.in.ray);
  if (!h || !h->front) return;
  if (f.in.fine != fine_) {  // the mode changes here: continue from where the widget is
    fine_ = f.in.fine;
    drag_anchor_ = h->pixel;
    drag_offset_ = drag_to_ - h->pixel;
  }
  drag_to_ = fine_ ? drag_anchor_ + drag_offset_ + (h->pixel - drag_anchor_) * settings_.fine_factor
                   : h->pixel + drag_offset_;
  f.change(press_, *held, [&] { held->drag_to(drag_to_); });
}

/// Release: end the drag; a click needs the release on the pressed widget.
void Pointer::release(Frame& f) {
  if (!f.in.trigger.released || press_.empty()) return;
  if (Widget* held = in_reach(f.panels, press_)) {
    held->set_pressed(false);
    if (held->draggable()) f.emit(press_, EventKind::DragEnd, drag_start_value_, held->value());
    if (hover_ == press_) {
      f.emit(press_, EventKind::Clicked, held->value(), held->value());
      f.change(press_, *held, [&] { held->click(hit_->pixel); });
    }
  }
  press_ = {};
}

/// Thumbstick (the sim's arrow keys): on the widget under the pointer, else the focused one. A
/// push steps once (a tap moves exactly one step); held past the repeat delay it moves
/// continuously. A gesture is bracketed by DragBegin/DragEnd (one undo step).
void Pointer::stick(Frame& f) {
  if (!press_.empty()) return;
  glm::dvec2 stick = f.in.thumbstick;
  if (std::abs(stick.x) < settings_.stick_dead_zone) stick.x = 0.0;
  if (std::abs(stick.y) < settings_.stick_dead_zone) stick.y = 0.0;
  const bool active = stick != glm::dvec2(0.0);
  if (active && !stick_active_) {
    Widget* h = in_reach(f.panels, hover_);
    stick_ref_ = h && h->steppable() ? hover_ : focus_;
  }
  Widget* w = in_reach(f.panels, stick_ref_);
  if (!w) {
    stick_active_ = false;
    stick_ref_ = {};
    return;
  }
  if (active && !stick_active_) {
    stick_active_ = true;
    stick_held_s_ = 0.0;
    stick_start_value_ = w->value();
    f.emit(stick_ref_, EventKind::DragBegin, stick_start_value_, stick_start_value_);
    const auto sign = [](double v) { return v > 0.0 ? 1 : v < 0.0 ? -1 : 0; };
    const glm::ivec2 dir{sign(stick.x), sign(stick.y)};
    f.change(stick_ref_, *w, [&] { w->step(dir); });
  } else if (active) {
    // Only the time held past the repeat delay moves it, whatever the frame rate.
    const double before = stick_held_s_;
    stick_held_s_ += f.dt;
    const double moving = stick_held_s_ - std::max(before, settings_.stick_repeat_delay_s);
    if (moving > 0.0) f.change(stick_ref_, *w, [&] { w->thumbstick(stick, moving); });
  }
  if (!active && stick_active_) {
    // Widgets reset their remainders on a zero deflection.
    f.change(stick_ref_, *w, [&] { w->thumbstick(glm::dvec2(0.0), f.dt); });
    stick_active_ = false;
    f.emit(stick_ref_, EventKind::DragEnd, stick_start_value_, w->value());
    stick_ref_ = {};
  }
}

}  // namespace vdfx::ui
