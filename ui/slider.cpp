/// @file
/// @brief Slider1D and Pad2D.
#include "ui/slider.h"

#include <algorithm>
#include <cmath>

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
constexpr double kHeaderHeight = 64.0;  // label/value row above the track or pad
constexpr double kThumbRadius = 20.0;
constexpr double kFooterHeight = 56.0;  // Pad2D's axis values below the pad

// Moves v by stick / sweep * dt of the track, in whole steps; the remainder waits in pending
// (in track fractions).
double stick_move(const Axis& a, double v, double stick, double dt, double& pending) {
  if (stick == 0.0) {
    pending = 0.0;
    return v;
  }
  pending += stick / kStickSweepSeconds * dt;
  const double unit = a.step > 0.0 && !a.log ? a.step / (a.max - a.min) : 0.0;
  if (unit <= 0.0) {
    const double out = a.at_fraction(a.fraction(v) + pending);
    pending = 0.0;
    return a.clamp_snap(out);
  }
  const double steps = std::trunc(pending / unit);
  pending -= steps * unit;
  return a.clamp_snap(v + steps * a.step);
}
}  // namespace

double Axis::clamp_snap(double v) const {
  if (step > 0.0 && !log) v = min + std::round((v - min) / step) * step;
  return std::clamp(v, std::min(min, max), std::max(min, max));
}

std::string Axis::text(double v) const {
  // A logarithmic track spans decades: as many decimals as the magnitude needs, no exponents.
  if (log) return format_value(v >= 10.0 ? "%.0f" : v >= 1.0 ? "%.1f" : "%.2f", v) + unit;
  return format_value(format, v) + unit;
}

double Axis::fraction(double v) const {
  if (log) return std::log(v / min) / std::log(max / min);
  return (v - min) / (max - min);
}

double Axis::at_fraction(double t) const {
  if (log) return min * std::pow(max / min, t);
  return min + t * (max - min);
}

double Axis::stepped(double v, int n) const {
  if (step > 0.0 && !log) return clamp_snap(v + n * step);
  return clamp_snap(at_fraction(fraction(v) + static_cast<double>(n) / kLogSteps));
}

std::string Axis::step_text() const {
  if (log) return "step \u00d7" + format_value("%.3g", std::pow(max / min, 1.0 / kLogSteps));
  if (step > 0.0) return "step " + format_value("%g", step);
  return "step " + format_value("%.3g", (max - min) / kLogSteps);
}

// ---- Slider1D ---------------------------------------------------------------------------------

Slider1D::Slider1D(std::string id, std::string label, Axis axis, double value, double origin)
    : Widget(std::move(id)),
      label_(std::move(label)),
      axis_(std::move(axis)),
      value_(axis_.clamp_snap(value)),
      origin_(std::clamp(origin, axis_.min, axis_.max)) {}

void Slider1D::set_value(double v) {
  set(value_, axis_.clamp_snap(v));
}

double Slider1D::track_x0() const {
  return rect().x + 24.0 + kThumbRadius;
}
double Slider1D::track_x1() const {
  return rect().right() - 24.0 - kThumbRadius;
}

void Slider1D::drag_to(glm::dvec2 p) {
  const double t = std::clamp((p.x - track_x0()) / (track_x1() - track_x0()), 0.0, 1.0);
  set_value(axis_.at_fraction(t));
}

std::optional<glm::dvec2> Slider1D::drag_point() const {
  return glm::dvec2(track_x0() + axis_.fraction(value_) * (track_x1() - track_x0()),
                    rect().centre().y);
}

void Slider1D::thumbstick(glm::dvec2 stick, double dt) {
  set_value(stick_move(axis_, value_, stick.x, dt, pending_));
}

void Slider1D::step(glm::ivec2 d) {
  // Right / up increase; a slider takes either axis of the stick or arrow keys.
  const int n = d.x != 0 ? d.x : d.y;
  if (n != 0) set_value(axis_.stepped(value_, n));
}

void Slider1D::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  draw_widget_frame(ctx, *this, r);
  const Rect header{r.x + t.padding, r.y + 6.0, r.w - 2 * t.padding, kHeaderHeight};
  const std::string value_text = axis_.text(value_);
  double vw = ctx.canvas.text_width(*ctx.fonts.regular, t.font_body, value_text);
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, value_text, header, Align::Right, t.text);
  if (hovered() || focused()) {
    // The step an arrow key or a stick push moves, beside the value while it is in reach, where
    // the label still fits beside both (a narrow slider keeps its label whole instead).
    const std::string step = axis_.step_text();
    const double label_w = ctx.canvas.text_width(*ctx.fonts.regular, t.font_body, label_);
    const double step_w = ctx.canvas.text_width(*ctx.fonts.regular, t.font_small, step);
    if (label_w + step_w + 2 * t.gap + vw <= header.w) {
      const Rect left_of_value{header.x, header.y, header.w - vw - t.gap, header.h};
      vw += t.gap + ctx.canvas.text(*ctx.fonts.regular, t.font_small, step, left_of_value,
                                    Align::Right, t.text_muted);
    }
  }
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, label_,
                  {header.x, header.y, header.w - vw - t.gap, header.h}, Align::Left, t.text);
  const double ty = r.y + kHeaderHeight + 0.5 * (r.h - kHeaderHeight);
  const double x0 = track_x0(), x1 = track_x1();
  auto x_of = [&](double v) { return x0 + axis_.fraction(v) * (x1 - x0); };
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
    : Widget(std::move(id)),
      label_(std::move(label)),
      x_(std::move(x)),
      y_(std::move(y)),
      value_(x_.clamp_snap(value.x), y_.clamp_snap(value.y)) {}

void Pad2D::set_value(glm::dvec2 v) {
  set(value_, glm::dvec2(x_.clamp_snap(v.x), y_.clamp_snap(v.y)));
}

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
  set_value({x_.at_fraction(tx), y_.at_fraction(ty)});
}

std::optional<glm::dvec2> Pad2D::drag_point() const {
  const Rect a = area();
  return glm::dvec2(a.x + x_.fraction(value_.x) * a.w, a.bottom() - y_.fraction(value_.y) * a.h);
}

void Pad2D::thumbstick(glm::dvec2 stick, double dt) {
  set_value({stick_move(x_, value_.x, stick.x, dt, pending_.x),
             stick_move(y_, value_.y, stick.y, dt, pending_.y)});
}

void Pad2D::step(glm::ivec2 d) {
  set_value({x_.stepped(value_.x, d.x), y_.stepped(value_.y, d.y)});
}

void Pad2D::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  draw_widget_frame(ctx, *this, r);
  const Rect header{r.x + t.padding, r.y + 6.0, r.w - 2 * t.padding, kHeaderHeight - 6.0};
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, label_, header, Align::Left, t.text);
  const Rect a = area();
  const std::string value_text =
      x_.name + " " + x_.text(value_.x) + "   " + y_.name + " " + y_.text(value_.y);
  ctx.canvas.text(*ctx.fonts.regular, t.font_small, value_text,
                  {header.x, a.bottom() + 6.0, header.w, kFooterHeight}, Align::Centre, t.text);
  ctx.canvas.fill_rounded_rect(a, 8.0, t.surface_pressed);
  for (int i = 1; i < 4; ++i) {  // quarter grid
    const double gx = a.x + a.w * i / 4.0, gy = a.y + a.h * i / 4.0;
    ctx.canvas.line({gx, a.y + 4}, {gx, a.bottom() - 4}, 2.0, t.track);
    ctx.canvas.line({a.x + 4, gy}, {a.right() - 4, gy}, 2.0, t.track);
  }
  ctx.canvas.push_clip(a);
  const double px = a.x + x_.fraction(value_.x) * a.w;
  const double py = a.bottom() - y_.fraction(value_.y) * a.h;
  ctx.canvas.line({px, a.y}, {px, a.bottom()}, 3.0, t.accent.with_alpha(0.6f));
  ctx.canvas.line({a.x, py}, {a.right(), py}, 3.0, t.accent.with_alpha(0.6f));
  ctx.canvas.pop_clip();
  const double rad = hovered() || pressed() ? kThumbRadius + 3.0 : kThumbRadius;
  ctx.canvas.fill_circle({px, py}, rad, t.text);
  ctx.canvas.stroke_circle({px, py}, rad - 3.0, 6.0, t.accent);
}

}  // namespace vdfx::ui
