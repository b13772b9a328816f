/// @file
/// @brief Minimap.
#include "ui/minimap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

#include "ui/canvas.h"
#include "ui/card.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
constexpr double kTitleH = 72.0;
}

Minimap::Minimap(std::string id, std::string title)
    : Widget(std::move(id)), title_(std::move(title)) {}

void Minimap::set_field(const cv::Mat& field, double lo, double hi) {
  cv::Mat u8, bgr;
  const double scale = hi > lo ? 255.0 / (hi - lo) : 0.0;
  field.convertTo(u8, CV_8U, scale, -lo * scale);
  cv::applyColorMap(u8, bgr, cv::COLORMAP_VIRIDIS);
  if (!image_.empty() && image_.size() == bgr.size() && image_.type() == bgr.type() &&
      cv::norm(image_, bgr, cv::NORM_INF) == 0.0)
    return;
  image_ = bgr;
  scaled_ = {};
  touch();
}

void Minimap::set_image(const cv::Mat& bgr) {
  image_ = bgr.clone();
  scaled_ = {};
  touch();
}

void Minimap::set_keyframes(std::vector<effects::Direction> dirs, int highlighted, int selected) {
  if (highlighted == highlighted_ && selected == selected_ && dirs == keyframes_) return;
  keyframes_ = std::move(dirs);
  highlighted_ = highlighted;
  selected_ = selected;
  touch();
}

void Minimap::set_coverage(int coverage_deg) {
  if (coverage_deg == coverage_deg_) return;
  coverage_deg_ = coverage_deg;
  touch();
}

void Minimap::set_view(effects::Direction forward, double hfov_deg, double vfov_deg) {
  if (forward == view_ && hfov_deg == hfov_ && vfov_deg == vfov_) return;
  view_ = forward;
  hfov_ = hfov_deg;
  vfov_ = vfov_deg;
  touch();
}

int Minimap::keyframe_at(glm::dvec2 p) const {
  const Rect a = map_area().inset(-kPickRadius);
  if (!a.contains(p)) return -1;
  int best = -1;
  double best_d = kPickRadius;
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    const double d = glm::length(to_pixel(keyframes_[i]) - p);
    if (d <= best_d) best = static_cast<int>(i), best_d = d;
  }
  return best;
}

void Minimap::click(glm::dvec2 p) {
  picked_ = keyframe_at(p);
  ++clicks_;
}

Rect Minimap::map_area() const {
  const Rect r = rect().inset(16.0);
  const Rect avail{r.x, rect().y + kTitleH, r.w, r.bottom() - rect().y - kTitleH};
  const double w = std::min(avail.w, 2.0 * avail.h);
  return {avail.centre().x - 0.5 * w, avail.y + 0.5 * (avail.h - 0.5 * w), w, 0.5 * w};
}

glm::dvec2 Minimap::to_pixel(const effects::Direction& d) const {
  const Rect a = map_area();
  const Eigen::Vector2d uv = effects::to_equirect_uv(d);
  return {a.x + uv.x() * a.w, a.y + uv.y() * a.h};
}

std::vector<std::vector<glm::dvec2>> Minimap::footprint() const {
  // Rays through the border of the view's image rectangle, in a frame whose right vector stays
  // horizontal (no roll), mapped onto the equirect image.
  const Eigen::Vector3d fwd = effects::to_unit(view_);
  const double az = view_.azimuth_deg * effects::kDegToRad;
  const Eigen::Vector3d right(std::cos(az), 0.0, std::sin(az));
  const Eigen::Vector3d up = right.cross(fwd).normalized();
  const double tx = std::tan(0.5 * hfov_ * effects::kDegToRad);
  const double ty = std::tan(0.5 * vfov_ * effects::kDegToRad);
  constexpr int kPerSide = 48;
  std::vector<Eigen::Vector2d> border;  // (sx, sy) in [-1, 1]^2, walked around the rectangle
  for (int i = 0; i < kPerSide; ++i) border.emplace_back(-1.0 + 2.0 * i / kPerSide, 1.0);
  for (int i = 0; i < kPerSide; ++i) border.emplace_back(1.0, 1.0 - 2.0 * i / kPerSide);
  for (int i = 0; i < kPerSide; ++i) border.emplace_back(1.0 - 2.0 * i / kPerSide, -1.0);
  for (int i = 0; i <= kPerSide; ++i) border.emplace_back(-1.0, -1.0 + 2.0 * i / kPerSide);
  std::vector<std::vector<glm::dvec2>> lines(1);
  const Rect a = map_area();
  double prev_u = -1.0;
  for (const auto& s : border) {
    const Eigen::Vector3d ray = fwd + right * (s.x() * tx) + up * (s.y() * ty);
    const Eigen::Vector2d uv = effects::to_equirect_uv(effects::from_unit(ray));
    if (prev_u >= 0.0 && std::abs(uv.x() - prev_u) > 0.5) lines.emplace_back();  // wrapped
    lines.back().push_back({a.x + uv.x() * a.w, a.y + uv.y() * a.h});
    prev_u = uv.x();
  }
  return lines;
}

void Minimap::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  Canvas& c = ctx.canvas;
  draw_titled_card(ctx, rect(), title_);
  const Rect a = map_area();
  if (!image_.empty())
    c.image(scaled_.get(image_, a, ChannelOrder::Bgr, c.scale()), a, ChannelOrder::Rgb);
  else
    c.fill_rect(a, t.surface_pressed);
  c.push_clip(a);
  if (coverage_deg_ < 360) {
    // Outside the video's coverage: dimmed, with a line at each edge of the covered part.
    const double side = a.w * (0.5 - coverage_deg_ / 720.0);
    const Rgba shade = Rgba::hex(0x000000, 0.65f);
    c.fill_rect({a.x, a.y, side, a.h}, shade);
    c.fill_rect({a.x + a.w - side, a.y, side, a.h}, shade);
    for (const double x : {a.x + side, a.x + a.w - side}) {
      const std::vector<glm::dvec2> edge{{x, a.y}, {x, a.y + a.h}};
      c.polyline(edge, 3.0, t.track);
    }
  }
  for (const auto& line : footprint()) {
    c.polyline(line, 7.0, Rgba::hex(0x000000, 0.7f));
    c.polyline(line, 3.5, t.text);
  }
  for (size_t i = 0; i < keyframes_.size(); ++i) {
    const glm::dvec2 p = to_pixel(keyframes_[i]);
    const bool hi = static_cast<int>(i) == highlighted_;
    c.fill_circle(p, hi ? 13.0 : 10.0, hi ? t.keyframe_highlight : t.keyframe);
    c.stroke_circle(p, hi ? 13.0 : 10.0, 3.0, Rgba::hex(0x000000, 0.8f));
    if (static_cast<int>(i) == selected_) {  // the keyframe being edited: a ring around its dot
      // Big and two-toned so it reads at a few eye pixels over any colour of the map.
      c.stroke_circle(p, 30.0, 12.0, Rgba::hex(0x000000, 0.8f));
      c.stroke_circle(p, 30.0, 6.0, t.text);
    }
  }
  c.pop_clip();
  c.stroke_rounded_rect(a.inset(-2.0), 2.0, 2.0, t.track);
}

}  // namespace vdfx::ui
