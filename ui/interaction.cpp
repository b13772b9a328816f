/// @file
/// @brief Ray hit testing and the Pointer state machine.
#include "ui/interaction.h"

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

Panel* Pointer::panel_of(std::span<Panel* const> panels, const std::string& id) {
  for (Panel* p : panels)
    if (p && p->id() == id) return p;
  return nullptr;
}

Widget* Pointer::widget_of(std::span<Panel* const> panels, const Ref& r) {
  if (r.empty()) return nullptr;
  Panel* p = panel_of(panels, r.panel);
  return p ? p->find(r.widget) : nullptr;
}

void Pointer::clear_focus(std::span<Panel* const> panels) {
  if (Widget* w = widget_of(panels, focus_)) w->set_focused(false);
  focus_ = {};
  stick_active_ = false;
}

std::vector<Event> Pointer::update(std::span<Panel* const> panels, const PointerInput& in,
                                   double dt) {
  std::vector<Event> events;
  auto emit = [&](const Ref& r, EventKind k, glm::dvec2 o, glm::dvec2 n) {
    events.push_back({r.panel, r.widget, k, o, n, widget_of(panels, r)});
  };
  // Runs a change on a widget and reports ValueChanged if its value moved.
  auto change = [&](const Ref& r, Widget& w, auto&& fn) {
    const glm::dvec2 before = w.value();
    fn();
    if (w.value() != before) emit(r, EventKind::ValueChanged, before, w.value());
  };

  // 1. Trigger with hysteresis.
  const bool was_down = down_;
  was_down_ = down_;
  if (!down_ && in.trigger > settings_.press_threshold)
    down_ = true;
  else if (down_ && in.trigger < settings_.release_threshold)
    down_ = false;

  // 2. Hit test and hover.
  hit_ = hit_panels(panels, in.ray);
  Ref now;
  if (hit_) {
    if (Widget* w = hit_->panel->widget_at(hit_->pixel)) now = {hit_->panel->id(), w->id()};
  }
  if (!(now == hover_)) {
    if (Widget* w = widget_of(panels, hover_)) w->set_hovered(false);
    hover_ = now;
  }
  if (Widget* w = widget_of(panels, hover_)) {
    w->set_hovered(true);
    w->hover_at(hit_->pixel);
  }

  // 3. Press: focus moves to the pressed widget; draggable widgets start following the ray.
  if (down_ && !was_down && !hover_.empty()) {
    press_ = hover_;
    Widget* w = widget_of(panels, press_);
    w->set_pressed(true);
    if (w->focusable() && !(focus_ == press_)) {
      if (Widget* f = widget_of(panels, focus_)) f->set_focused(false);
      focus_ = press_;
      stick_active_ = false;
      w->set_focused(true);
    }
    if (w->draggable()) {
      drag_start_value_ = w->value();
      emit(press_, EventKind::DragBegin, drag_start_value_, drag_start_value_);
      fine_ = in.fine;
      drag_anchor_ = hit_->pixel;
      // A fine press keeps the value where it is (the motion from here moves it); a plain press
      // jumps it under the pointer.
      drag_to_ = fine_ ? w->drag_point().value_or(hit_->pixel) : hit_->pixel;
      drag_offset_ = drag_to_ - hit_->pixel;
      if (!fine_) change(press_, *w, [&] { w->drag_to(hit_->pixel); });
    }
  }

  // 4. Held: follow the ray on the pressed widget's panel plane, even past its edges.
  Widget* held = widget_of(panels, press_);
  if (down_ && was_down && held && held->draggable()) {
    if (const auto h = intersect_panel_plane(*panel_of(panels, press_.panel), in.ray);
        h && h->front) {
      if (in.fine != fine_) {  // the mode changes here: continue from where the widget is
        fine_ = in.fine;
        drag_anchor_ = h->pixel;
        drag_offset_ = drag_to_ - h->pixel;
      }
      drag_to_ =
          fine_ ? drag_anchor_ + drag_offset_ + (h->pixel - drag_anchor_) * settings_.fine_factor
                : h->pixel + drag_offset_;
      change(press_, *held, [&] { held->drag_to(drag_to_); });
    }
  }

  // 5. Release: end the drag; a click needs the release on the pressed widget.
  if (!down_ && was_down && !press_.empty()) {
    if (held) {
      held->set_pressed(false);
      if (held->draggable()) emit(press_, EventKind::DragEnd, drag_start_value_, held->value());
      if (hover_ == press_) {
        emit(press_, EventKind::Clicked, held->value(), held->value());
        change(press_, *held, [&] { held->click(hit_->pixel); });
      }
    }
    press_ = {};
  }

  // 6. Thumbstick (the sim's arrow keys): on the widget under the pointer, else the focused one.
  // A push steps once (a tap moves exactly one step); held past the repeat delay it moves
  // continuously. A gesture is bracketed by DragBegin/DragEnd (one undo step).
  if (press_.empty()) {
    glm::dvec2 stick = in.thumbstick;
    if (std::abs(stick.x) < settings_.stick_dead_zone) stick.x = 0.0;
    if (std::abs(stick.y) < settings_.stick_dead_zone) stick.y = 0.0;
    const bool active = stick != glm::dvec2(0.0);
    if (active && !stick_active_) {
      Widget* h = widget_of(panels, hover_);
      stick_ref_ = h && h->steppable() ? hover_ : focus_;
    }
    if (Widget* f = widget_of(panels, stick_ref_)) {
      if (active && !stick_active_) {
        stick_active_ = true;
        stick_held_s_ = 0.0;
        stick_start_value_ = f->value();
        emit(stick_ref_, EventKind::DragBegin, stick_start_value_, stick_start_value_);
        const glm::ivec2 dir{stick.x > 0.0   ? 1
                             : stick.x < 0.0 ? -1
                                             : 0,
                             stick.y > 0.0   ? 1
                             : stick.y < 0.0 ? -1
                                             : 0};
        change(stick_ref_, *f, [&] { f->step(dir); });
      } else if (active) {
        // Only the time held past the repeat delay moves it, whatever the frame rate.
        const double before = stick_held_s_;
        stick_held_s_ += dt;
        const double moving = stick_held_s_ - std::max(before, settings_.stick_repeat_delay_s);
        if (moving > 0.0) change(stick_ref_, *f, [&] { f->thumbstick(stick, moving); });
      }
      if (!active && stick_active_) {
        change(stick_ref_, *f,
               [&] { f->thumbstick(glm::dvec2(0.0), dt); });  // widgets reset their remainders
        stick_active_ = false;
        emit(stick_ref_, EventKind::DragEnd, stick_start_value_, f->value());
        stick_ref_ = {};
      }
    } else {
      stick_active_ = false;
      stick_ref_ = {};
    }
  }
  return events;
}

}  // namespace vdfx::ui
