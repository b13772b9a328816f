/// @file
/// @brief Plot.
#include "ui/plot.h"

#include <algorithm>

#include "ui/canvas.h"
#include "ui/card.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
constexpr double kTitleH = 84.0, kAxisW = 110.0, kAxisH = 48.0;
}

Plot::Plot(std::string id, std::string title, double y_min, double y_max, const char* y_format)
    : Widget(std::move(id)),
      title_(std::move(title)),
      y_min_(y_min),
      y_max_(y_max),
      y_format_(y_format) {}

void Plot::set_values(std::vector<double> values) {
  set(values_, values);
}
void Plot::set_range(double lo, double hi) {
  set(y_min_, lo), set(y_max_, hi);
}
void Plot::set_keyframes(std::vector<int> frames) {
  set(keyframes_, frames);
}
void Plot::set_playhead(int frame) {
  if (frame == playhead_) return;
  const int old = playhead_;
  playhead_ = frame;
  // Outside the sampled frames the playhead draws nothing: no damage there.
  for (const Rect& r : {playhead_area(old), playhead_area(frame)})
    if (!r.empty()) touch(r);
}

Rect Plot::playhead_area(int frame) const {
  const int n = static_cast<int>(values_.size());
  if (frame < 0 || frame >= n) return {};
  // The 3 px line and a keyframe dot (10 px + outline) that turns highlighted under it.
  constexpr double kHalf = 16.0;
  const Rect a = plot_area();
  const double x = n > 1 ? a.x + a.w * frame / (n - 1) : a.x;
  return {x - kHalf, a.y - kHalf, 2 * kHalf, a.h + 2 * kHalf};
}

Rect Plot::plot_area() const {
  const Rect r = rect();
  return {r.x + kAxisW, r.y + kTitleH, r.w - kAxisW - 24.0, r.h - kTitleH - kAxisH};
}

void Plot::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  Canvas& c = ctx.canvas;
  const Rect r = rect();
  draw_titled_card(ctx, r, title_);
  const Rect a = plot_area();
  const int n = static_cast<int>(values_.size());
  auto xf = [&](double f) { return n > 1 ? a.x + a.w * f / (n - 1) : a.x; };
  auto yf = [&](double v) {
    return a.bottom() - (std::clamp(v, y_min_, y_max_) - y_min_) / (y_max_ - y_min_) * a.h;
  };
  // Grid: bottom, middle and top with their values on the left.
  for (int i = 0; i <= 2; ++i) {
    const double v = y_min_ + (y_max_ - y_min_) * i / 2.0;
    const double y = yf(v);
    c.line({a.x, y}, {a.right(), y}, i == 0 ? 3.0 : 2.0, t.track);
    c.text(*ctx.fonts.regular, t.font_small, format_value(y_format_, v),
           {r.x + 8, y - 24, kAxisW - 20, 48}, Align::Right, t.text_muted);
  }
  c.line({a.x, a.y}, {a.x, a.bottom()}, 3.0, t.track);
  const Rect xl{a.x, a.bottom() + 4, a.w, kAxisH - 4};
  c.text(*ctx.fonts.regular, t.font_small, "0", xl, Align::Left, t.text_muted);
  c.text(*ctx.fonts.regular, t.font_small, std::to_string(std::max(0, n - 1)), xl, Align::Right,
         t.text_muted);
  c.text(*ctx.fonts.regular, t.font_small, "frame", xl, Align::Centre, t.text_muted);
  if (playhead_ >= 0 && playhead_ < n)
    c.line({xf(playhead_), a.y}, {xf(playhead_), a.bottom()}, 3.0, t.playhead);
  std::vector<glm::dvec2> pts;
  pts.reserve(values_.size());
  for (int i = 0; i < n; ++i) pts.push_back({xf(i), yf(values_[static_cast<size_t>(i)])});
  c.push_clip(a.inset(-14.0));  // room for keyframe dots at the ends
  c.polyline(pts, 4.0, t.plot_line);
  for (int f : keyframes_)
    if (f >= 0 && f < n) {
      const glm::dvec2 p{xf(f), yf(values_[static_cast<size_t>(f)])};
      c.fill_circle(p, 10.0, f == playhead_ ? t.keyframe_highlight : t.keyframe);
      c.stroke_circle(p, 10.0, 3.0, t.surface);
    }
  c.pop_clip();
}

}  // namespace vdfx::ui
