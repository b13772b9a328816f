/// @file
/// @brief Panel.
#include "ui/panel.h"

#include <algorithm>
#include <cmath>

#include "ui/canvas.h"

namespace vdfx::ui {

Panel::Panel(std::string id, int width_px, int height_px, glm::dvec2 size_m,
             std::shared_ptr<const FontSet> fonts, const Theme& theme)
    : id_(std::move(id)),
      width_(width_px),
      height_(height_px),
      size_m_(size_m),
      fonts_(std::move(fonts)),
      theme_(theme) {}

void Panel::set_render_scale(double scale) {
  if (scale == scale_) return;
  scale_ = scale;
  canvas_.reset();  // a new texture size: the next render is full
  ++revision_;
}

int Panel::texture_width() const {
  return std::max(1, static_cast<int>(std::lround(width_ * scale_)));
}
int Panel::texture_height() const {
  return std::max(1, static_cast<int>(std::lround(height_ * scale_)));
}

Widget* Panel::find(std::string_view id) const {
  for (const auto& w : widgets_)
    if (w->id() == id) return w.get();
  return nullptr;
}

Widget* Panel::widget_at(glm::dvec2 pixel) const {
  for (auto it = widgets_.rbegin(); it != widgets_.rend(); ++it)
    if ((*it)->interactive() && (*it)->hit(pixel)) return it->get();
  return nullptr;
}

void Panel::set_world_pose(const Pose& world) {
  world_ = world;
  attached_ = false;
}

void Panel::attach_to_hand(const Pose& grip_to_panel) {
  offset_ = grip_to_panel;
  attached_ = true;
}

void Panel::attach_keeping_pose(const Pose& grip_world) {
  attach_to_hand(grip_world.inverse() * world_);
}

void Panel::update_hand(const Pose& grip_world) {
  if (attached_) world_ = grip_world * offset_;
}

glm::dvec2 Panel::pixel_of_local(glm::dvec2 l) const {
  return {(l.x / size_m_.x + 0.5) * width_, (0.5 - l.y / size_m_.y) * height_};
}

glm::dvec2 Panel::local_of_pixel(glm::dvec2 p) const {
  return {(p.x / width_ - 0.5) * size_m_.x, (0.5 - p.y / height_) * size_m_.y};
}

glm::dvec3 Panel::world_of_pixel(glm::dvec2 pixel) const {
  const glm::dvec2 l = local_of_pixel(pixel);
  return world_.transform({l.x, l.y, 0.0});
}

namespace {

/// r grown to whole pixels and cut to the panel.
Rect snap(const Rect& r, const Rect& panel) {
  const double x0 = std::floor(r.x), y0 = std::floor(r.y);
  return Rect{x0, y0, std::ceil(r.right()) - x0, std::ceil(r.bottom()) - y0}.intersect(panel);
}

Rect bounding(const Rect& a, const Rect& b) {
  const double x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  return {x0, y0, std::max(a.right(), b.right()) - x0, std::max(a.bottom(), b.bottom()) - y0};
}

/// Adds r to a set of disjoint rectangles, merging it with every one it overlaps (each pixel is
/// then redrawn once).
void add_merged(std::vector<Rect>& rects, Rect r) {
  if (r.empty()) return;
  for (bool merged = true; merged;) {
    merged = false;
    for (auto it = rects.begin(); it != rects.end(); ++it)
      if (!it->intersect(r).empty()) {
        r = bounding(r, *it);
        rects.erase(it);
        merged = true;
        break;
      }
  }
  rects.push_back(r);
}

}  // namespace

Panel::~Panel() = default;

Panel::Damage Panel::damage() const {
  // Widgets report damage in layout pixels; it is redrawn in whole texture pixels.
  const Rect all = whole_texture();
  if (!canvas_ || rendered_revision_ != revision_ ||
      rendered_widget_revisions_.size() != widgets_.size())
    return {{all}, true};
  const auto tex = [&](const Rect& r) {
    return snap(Rect{r.x * scale_, r.y * scale_, r.w * scale_, r.h * scale_}, all);
  };
  Damage d;
  for (size_t i = 0; i < widgets_.size(); ++i) {
    const Widget& w = *widgets_[i];
    if (w.revision() == rendered_widget_revisions_[i]) continue;
    if (w.damage_is_partial()) {  // the widget knows which part changed
      add_merged(d.rects, tex(w.damage().intersect(w.paint_bounds())));
      continue;
    }
    add_merged(d.rects, tex(rendered_bounds_[i]));  // where it was
    add_merged(d.rects, tex(w.paint_bounds()));     // where it is
  }
  if (d.rects.empty()) return d;
  double area = 0.0;
  for (const Rect& r : d.rects) area += r.w * r.h;
  if (!partial_ || area > kFullRenderFraction * all.w * all.h) return {{all}, true};
  return d;
}

std::vector<Rect> Panel::dirty_rects() const {
  return damage().rects;
}

bool Panel::dirty() const {
  return !damage().rects.empty();
}

void Panel::draw_region(Canvas& canvas, const Rect* clip) const {
  const Rect all = whole();
  canvas.fill_rounded_rect(all, 2 * theme_.corner_radius, theme_.panel_bg);
  canvas.stroke_rounded_rect(all, 2 * theme_.corner_radius, 3.0, theme_.panel_border);
  DrawContext ctx{canvas, theme_, *fonts_};
  for (const auto& w : widgets_) {
    if (w->rect().empty()) continue;  // laid out away (a widget of another mode)
    if (!clip || !w->paint_bounds().intersect(*clip).empty()) w->draw(ctx);
  }
}

bool Panel::render_if_dirty() {
  const Damage dmg = damage();
  if (dmg.rects.empty()) return false;
  // Someone still holds the last texture: draw into a new buffer so theirs stays as it was.
  const bool shared = canvas_ && canvas_->image().u && canvas_->image().u->refcount > 1;
  if (dmg.full) {
    if (!canvas_ || shared) {
      canvas_ = std::make_unique<Canvas>(texture_width(), texture_height());
      canvas_->set_scale(scale_);
    } else {
      canvas_->clear();
    }
    draw_region(*canvas_, nullptr);
    ++full_render_count_;
  } else {
    if (shared) {
      canvas_ = std::make_unique<Canvas>(canvas_->image().clone());
      canvas_->set_scale(scale_);
    }
    for (const Rect& px : dmg.rects) {
      const Rect r{px.x / scale_, px.y / scale_, px.w / scale_, px.h / scale_};  // layout pixels
      canvas_->push_clip(r);
      canvas_->clear_rect(r);
      draw_region(*canvas_, &r);
      canvas_->pop_clip();
    }
  }
  rendered_revision_ = revision_;
  rendered_widget_revisions_.resize(widgets_.size());
  rendered_bounds_.resize(widgets_.size());
  for (size_t i = 0; i < widgets_.size(); ++i) {
    rendered_widget_revisions_[i] = widgets_[i]->revision();
    rendered_bounds_[i] = widgets_[i]->paint_bounds();
    widgets_[i]->reset_damage();
  }
  ++render_count_;
  return true;
}

const cv::Mat& Panel::texture() {
  render_if_dirty();
  return canvas_->image();
}

}  // namespace vdfx::ui
