/// @file
/// @brief Panel.
#include "ui/panel.h"

#include "ui/canvas.h"

namespace vdfx::ui {

Panel::Panel(std::string id, int width_px, int height_px, glm::dvec2 size_m,
             std::shared_ptr<const FontSet> fonts, const Theme& theme)
    : id_(std::move(id)), width_(width_px), height_(height_px), size_m_(size_m),
      fonts_(std::move(fonts)), theme_(theme) {}

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

std::uint64_t Panel::state_revision() const {
  // Revisions only grow, so the sum changes whenever any of them does.
  std::uint64_t sum = revision_;
  for (const auto& w : widgets_) sum += w->revision();
  return sum;
}

bool Panel::dirty() const { return rendered_revision_ != state_revision(); }

bool Panel::render_if_dirty() {
  if (!dirty()) return false;
  Canvas canvas(width_, height_);
  const Rect all{0, 0, static_cast<double>(width_), static_cast<double>(height_)};
  canvas.fill_rounded_rect(all, 2 * theme_.corner_radius, theme_.panel_bg);
  canvas.stroke_rounded_rect(all, 2 * theme_.corner_radius, 3.0, theme_.panel_border);
  DrawContext ctx{canvas, theme_, *fonts_};
  for (const auto& w : widgets_) w->draw(ctx);
  texture_ = canvas.image();
  rendered_revision_ = state_revision();
  ++render_count_;
  return true;
}

const cv::Mat& Panel::texture() {
  render_if_dirty();
  return texture_;
}

}  // namespace vdfx::ui
