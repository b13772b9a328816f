/// @file
/// @brief ColourWheel and the hue/saturation <-> tint gain conversions.
#include "ui/colour_wheel.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "effects/effect_types.h"
#include "ui/canvas.h"
#include "ui/colour.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
constexpr double kHeaderHeight = 64.0;
constexpr double kDeg = 180.0 / std::numbers::pi;
double wrap360(double h) {
  return std::fmod(std::fmod(h, 360.0) + 360.0, 360.0);
}
}  // namespace

Eigen::Vector3d tint_gain_from_hue_sat(double hue_deg, double sat) {
  const Rgba c = hsv(hue_deg, std::clamp(sat, 0.0, 1.0), 1.0);
  return effects::normalize_tint({c.r, c.g, c.b});
}

glm::dvec2 hue_sat_from_tint_gain(const Eigen::Vector3d& g) {
  const double mx = g.maxCoeff(), mn = g.minCoeff();
  if (!(mx > 0.0)) return {0.0, 0.0};
  const double sat = std::clamp(1.0 - mn / mx, 0.0, 1.0);
  const double d = mx - mn;
  if (d <= 0.0) return {0.0, 0.0};
  double h = 0.0;  // the usual hexcone hue of (r, g, b)
  if (mx == g.x())
    h = 60.0 * std::fmod((g.y() - g.z()) / d, 6.0);
  else if (mx == g.y())
    h = 60.0 * ((g.z() - g.x()) / d + 2.0);
  else
    h = 60.0 * ((g.x() - g.y()) / d + 4.0);
  return {wrap360(h), sat};
}

ColourWheel::ColourWheel(std::string id, std::string label, double hue_deg, double sat)
    : Widget(std::move(id)),
      label_(std::move(label)),
      hue_(wrap360(hue_deg)),
      sat_(std::clamp(sat, 0.0, 1.0)) {}

void ColourWheel::set_hue_sat(double hue_deg, double sat) {
  set(hue_, wrap360(hue_deg));
  set(sat_, std::clamp(sat, 0.0, 1.0));
}

glm::dvec2 ColourWheel::disc_centre() const {
  const Rect r = rect();
  return {r.x + 24.0 + disc_radius(), r.y + kHeaderHeight + 0.5 * (r.h - kHeaderHeight)};
}

double ColourWheel::disc_radius() const {
  const Rect r = rect();
  return std::max(0.0, 0.5 * std::min(r.w * 0.62, r.h - kHeaderHeight - 24.0));
}

void ColourWheel::drag_to(glm::dvec2 p) {
  const glm::dvec2 d = p - disc_centre();
  const double len = glm::length(d);
  // Screen y points down, hue turns counter-clockwise as seen.
  const double hue = len > 0.0 ? std::atan2(-d.y, d.x) * kDeg : hue_;
  set_hue_sat(hue, len / disc_radius());
}

void ColourWheel::step(glm::ivec2 d) {
  set_hue_sat(hue_ + kHueStepDeg * d.x, sat_ + kSatStep * d.y);
}

void ColourWheel::thumbstick(glm::dvec2 stick, double dt) {
  if (stick == glm::dvec2(0.0)) return;
  set_hue_sat(hue_ + stick.x * 120.0 * dt, sat_ + stick.y * 0.5 * dt);
}

void ColourWheel::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  draw_widget_frame(ctx, *this, r);
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, label_,
                  {r.x + t.padding, r.y + 6.0, r.w - 2 * t.padding, kHeaderHeight - 6.0},
                  Align::Left, t.text);
  const glm::dvec2 c = disc_centre();
  const double rad = disc_radius();
  const int n = static_cast<int>(std::ceil(2 * rad));
  if (n > 0 && wheel_radius_ != rad) {  // the disc as an image with an anti-aliased rim in alpha
    cv::Mat wheel(n, n, CV_8UC4);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double dx = x + 0.5 - 0.5 * n, dy = y + 0.5 - 0.5 * n;
        const double dist = std::hypot(dx, dy);
        const Rgba col = hsv(std::atan2(-dy, dx) * kDeg, std::min(1.0, dist / rad), 1.0);
        const double a = std::clamp(rad - dist + 0.5, 0.0, 1.0);
        wheel.at<cv::Vec4b>(y, x) = cv::Vec4b(
            cv::saturate_cast<uchar>(col.r * 255.0), cv::saturate_cast<uchar>(col.g * 255.0),
            cv::saturate_cast<uchar>(col.b * 255.0), cv::saturate_cast<uchar>(a * 255.0));
      }
    wheel_ = wheel;
    wheel_radius_ = rad;
  }
  if (n > 0)
    ctx.canvas.image(wheel_, {c.x - 0.5 * n, c.y - 0.5 * n, double(n), double(n)},
                     ChannelOrder::Rgb);
  const double ang = hue_ / kDeg;
  const glm::dvec2 m = c + sat_ * rad * glm::dvec2(std::cos(ang), -std::sin(ang));
  ctx.canvas.stroke_circle(m, 16.0, 8.0, Rgba::hex(0x000000, 0.8f));
  ctx.canvas.stroke_circle(m, 16.0, 4.0, t.text);
  // Swatch and numbers to the right of the disc: the normalised gain is what the effect uses.
  const Eigen::Vector3d g = tint_gain();
  const double sx = c.x + rad + t.padding;
  const Rect info{sx, c.y - rad, r.right() - t.padding - sx, 2 * rad};
  const Rgba swatch = hsv(hue_, sat_, 1.0);
  ctx.canvas.fill_rounded_rect({info.x, info.y, info.w, 72.0}, 10.0, swatch);
  const int px = t.font_small;
  const double lh = px * 1.25;
  double y = info.y + 72.0 + 12.0;
  const std::string lines[] = {
      "hue " + format_value("%.0f", hue_) + "\u00b0", "sat " + format_value("%.2f", sat_),
      "r " + format_value("%.2f", g.x()), "g " + format_value("%.2f", g.y()),
      "b " + format_value("%.2f", g.z())};
  for (const auto& s : lines) {
    ctx.canvas.text(*ctx.fonts.regular, px, s, {info.x, y, info.w, lh}, Align::Left,
                    &s == &lines[0] || &s == &lines[1] ? t.text : t.text_muted);
    y += lh;
  }
}

}  // namespace vdfx::ui
