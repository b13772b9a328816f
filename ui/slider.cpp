/// @file
/// @brief Slider1D and Pad2D.
#include "ui/slider.h"

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

#include <algorithm>
#include <cmath>

namespace vdfx::ui {

namespace {
constexpr double kHeaderHeight = 64.0;  // label/value row above the track or pad
constexpr double kThumbRadius = 20.0;
constexpr double kFooterHeight = 56.0;  // Pad2D's axis values below the pad

// Moves v by stick * range / sweep * dt, in whole steps; the remainder waits in pending.
double stick_move(const Axis& a, double v, double stick, double dt, double& pending) {
  if (stick == 0.0) {
    pending = 0.0;
    return v;
  }
  pending += stick * (a.max - a.min) / kStickSweepSeconds * dt;
  if (a.step <= 0.0) {
    const double out = v + pending;
    pending = 0.0;
    return a.clamp_snap(out);
  }
  const double steps = std::trunc(pending / a.step);
  pending -= steps * a.step;
  return a.clamp_snap(v + steps * a.step);
}
}  // namespace

double Axis::clamp_snap(double v) const {
  if (step > 0.0) v = min + std::round((v - min) / step) * step;
  return std::clamp(v, std::min(min, max), std::max(min, max));
}

std::string Axis::text(double v) const { return format_value(format, v) + unit; }

// ---- Slider1D ---------------------------------------------------------------------------------

Slider1D::Slider1D(std::string id, std::string label, Axis axis, double value, double origin)
    : Widget(std::move(id)), label_(std::move(label)), axis_(std::move(axis)),
      value_(axis_.clamp_snap(value)), origin_(std::clamp(origin, axis_.min, axis_.max)) {}

void Slider1D::set_value(double v) { set(value_, axis_.clamp_snap(v)); }

double Slider1D::track_x0() const { return rect().x + 24.0 + kThumbRadius; }
double Slider1D::track_x1() const { return rect().right() - 24.0 - kThumbRadius; }

void Slider1D::drag_to(glm::dvec2 p) {
  const double t = std::clamp((p.x - track_x0()) / (track_x1() - track_x0()), 0.0, 1.0);
  set_value(axis_.min + t * (axis_.max - axis_.min));
}

void Slider1D::thumbstick(glm::dvec2 stick, double dt) {
  set_value(stick_move(axis_, value_, stick.x, dt, pending_));
}

void Slider1D::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  draw_widget_frame(ctx, *this, r);
  const Rect header{r.x + t.padding, r.y + 6.0, r.w - 2 * t.padding, kHeaderHeight};
  const std::string value_text = axis_.text(value_);
  const double vw = ctx.fonts.regular->measure(value_text, t.font_body);
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, label_,
                  {header.x, header.y, header.w - vw - t.gap, header.h}, Align::Left, t.text);
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, value_text, header, Align::Right, t.text);
  const double ty = r.y + kHeaderHeight + 0.5 * (r.h - kHeaderHeight);
  const double x0 = track_x0(), x1 = track_x1();
  auto x_of = [&](double v) { return x0 + (v - axis_.min) / (axis_.max - axis_.min) * (x1 - x0); };
  const double th = 12.0;
  ctx.canvas.fill_rounded_rect({x0, ty - 0.5 * th, x1 - x0, th}, 0.5 * th, t.track);
  const double a = x_of(origin_), b = x_of(value_);
  ctx.canvas.fill_rounded_rect({std::min(a, b), ty - 0.5 * th, std::abs(b - a), th}, 0.5 * th,
                               t.accent);
  ctx.canvas.fill_rect({a - 1.5, ty - 14.0, 3.0, 28.0}, t.text_muted);  // neutral tick
  const double rad = hovered() || pressed() ? kThumbRadius + 3.0 : kThumbRadius;
  ctx.canvas.fill_circle({b, ty}, rad, t.text);
  ctx.canvas.stroke_circle({b, ty}, rad - 3.0, 6.0, t.accent);
}

// ---- Pad2D ------------------------------------------------------------------------------------

Pad2D::Pad2D(std::string id, std::string label, Axis x, Axis y, glm::dvec2 value)
    : Widget(std::move(id)), label_(std::move(label)), x_(std::move(x)), y_(std::move(y)),
      value_(x_.clamp_snap(value.x), y_.clamp_snap(value.y)) {}

void Pad2D::set_value(glm::dvec2 v) { set(value_, glm::dvec2(x_.clamp_snap(v.x), y_.clamp_snap(v.y))); }

Rect Pad2D::area() const {
  const Rect r = rect();
  const double avail_h = r.h - kHeaderHeight - kFooterHeight - 12.0;
  const double side = std::max(0.0, std::min(r.w - 48.0, avail_h));
  return {r.centre().x - 0.5 * side, r.y + kHeaderHeight, side, side};
}

void Pad2D::drag_to(glm::dvec2 p) {
  const Rect a = area();
  const double tx = std::clamp((p.x - a.x) / a.w, 0.0, 1.0);
  const double ty = std::clamp((a.bottom() - p.y) / a.h, 0.0, 1.0);
  set_value({x_.min + tx * (x_.max - x_.min), y_.min + ty * (y_.max - y_.min)});
}

void Pad2D::thumbstick(glm::dvec2 stick, double dt) {
  set_value({stick_move(x_, value_.x, stick.x, dt, pending_.x),
             stick_move(y_, value_.y, stick.y, dt, pending_.y)});
}

void Pad2D::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  draw_widget_frame(ctx, *this, r);
  const Rect header{r.x + t.padding, r.y + 6.0, r.w - 2 * t.padding, kHeaderHeight - 6.0};
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, label_, header, Align::Left, t.text);
  const Rect a = area();
  const std::string value_text = x_.name + " " + x_.text(value_.x) + "   " + y_.name + " " +
                                 y_.text(value_.y);
  ctx.canvas.text(*ctx.fonts.regular, t.font_small, value_text,
                  {header.x, a.bottom() + 6.0, header.w, kFooterHeight}, Align::Centre, t.text);
  ctx.canvas.fill_rounded_rect(a, 8.0, t.surface_pressed);
  for (int i = 1; i < 4; ++i) {  // quarter grid
    const double gx = a.x + a.w * i / 4.0, gy = a.y + a.h * i / 4.0;
    ctx.canvas.line({gx, a.y + 4}, {gx, a.bottom() - 4}, 2.0, t.track);
    ctx.canvas.line({a.x + 4, gy}, {a.right() - 4, gy}, 2.0, t.track);
  }
  ctx.canvas.push_clip(a);
  const double px = a.x + (value_.x - x_.min) / (x_.max - x_.min) * a.w;
  const double py = a.bottom() - (value_.y - y_.min) / (y_.max - y_.min) * a.h;
  ctx.canvas.line({px, a.y}, {px, a.bottom()}, 3.0, t.accent.with_alpha(0.6f));
  ctx.canvas.line({a.x, py}, {a.right(), py}, 3.0, t.accent.with_alpha(0.6f));
  ctx.canvas.pop_clip();
  const double rad = hovered() || pressed() ? kThumbRadius + 3.0 : kThumbRadius;
  ctx.canvas.fill_circle({px, py}, rad, t.text);
  ctx.canvas.stroke_circle({px, py}, rad - 3.0, 6.0, t.accent);
}

}  // namespace vdfx::ui
