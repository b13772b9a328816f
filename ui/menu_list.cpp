/// @file
/// @brief MenuList.
#include "ui/menu_list.h"

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

#include <algorithm>
#include <cmath>

namespace vdfx::ui {

namespace {
constexpr double kInset = 8.0;  // rows sit this far inside the frame
}

MenuList::MenuList(std::string id, std::vector<std::string> items, int selected,
                   double row_height)
    : Widget(std::move(id)), items_(std::move(items)), selected_(0), row_h_(row_height) {
  select(selected);
}

void MenuList::set_items(std::vector<std::string> items) {
  set(items_, items);
  select(selected_);
}

int MenuList::visible_rows() const {
  return std::max(1, static_cast<int>(std::floor((rect().h - 2 * kInset) / row_h_)));
}

void MenuList::set_scroll(int first) {
  const int max_first = std::max(0, static_cast<int>(items_.size()) - visible_rows());
  set(scroll_, std::clamp(first, 0, max_first));
}

void MenuList::select(int index) {
  if (items_.empty()) return set(selected_, 0);
  set(selected_, std::clamp(index, 0, static_cast<int>(items_.size()) - 1));
  if (rect().empty()) return;  // scrolled into view once laid out
  if (selected_ < scroll_) set_scroll(selected_);
  if (selected_ >= scroll_ + visible_rows()) set_scroll(selected_ - visible_rows() + 1);
}

int MenuList::row_at(glm::dvec2 p) const {
  if (!rect().contains(p)) return -1;
  const int row = static_cast<int>(std::floor((p.y - rect().y - kInset) / row_h_));
  if (row < 0 || row >= visible_rows()) return -1;
  const int index = scroll_ + row;
  return index < static_cast<int>(items_.size()) ? index : -1;
}

void MenuList::hover_at(glm::dvec2 p) {
  const int row = row_at(p);
  if (row == hover_row_) return;
  // Only the rows losing and gaining the highlight change (1 px more for anti-aliasing).
  const Rect r = rect();
  auto band = [&](int index) {
    return Rect{r.x, r.y + kInset + (index - scroll_) * row_h_ - 1.0, r.w, row_h_ + 2.0};
  };
  const int old = hover_row_;
  hover_row_ = row;
  if (old >= 0) touch(band(old));
  if (row >= 0) touch(band(row));
}

void MenuList::click(glm::dvec2 p) {
  if (const int row = row_at(p); row >= 0) select(row);
}

void MenuList::step(glm::ivec2 d) {
  if (d.y != 0) select(selected_ - d.y);  // up = the previous item
}

void MenuList::thumbstick(glm::dvec2 stick, double dt) {
  if (std::abs(stick.y) < 0.5) {
    held_ = 0.0;
    return;
  }
  held_ += dt;
  for (; held_ >= kRepeatSeconds; held_ -= kRepeatSeconds) select(selected_ + (stick.y > 0 ? -1 : 1));
}

void MenuList::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  ctx.canvas.fill_rounded_rect(r, t.corner_radius, t.surface);
  if (focused()) ctx.canvas.stroke_rounded_rect(r, t.corner_radius, t.focus_width, t.accent);
  const bool scrolls = static_cast<int>(items_.size()) > visible_rows();
  const double bar_w = scrolls ? 14.0 : 0.0;
  ctx.canvas.push_clip(r.inset(kInset));
  for (int row = 0; row < visible_rows(); ++row) {
    const int i = scroll_ + row;
    if (i >= static_cast<int>(items_.size())) break;
    const Rect rr{r.x + kInset, r.y + kInset + row * row_h_, r.w - 2 * kInset - bar_w - 4.0,
                  row_h_ - 4.0};
    if (i == selected_) ctx.canvas.fill_rounded_rect(rr, t.corner_radius - 4, t.selection);
    else if (i == hover_row_ && hovered())
      ctx.canvas.fill_rounded_rect(rr, t.corner_radius - 4, t.surface_hover);
    ctx.canvas.text(*ctx.fonts.regular, t.font_body, items_[static_cast<size_t>(i)],
                    rr.inset(t.padding - kInset, 0), Align::Left, t.text);
  }
  ctx.canvas.pop_clip();
  if (scrolls) {
    const Rect track{r.right() - kInset - bar_w, r.y + kInset, bar_w, r.h - 2 * kInset};
    ctx.canvas.fill_rounded_rect(track, 0.5 * bar_w, t.track);
    const double n = static_cast<double>(items_.size());
    ctx.canvas.fill_rounded_rect({track.x, track.y + track.h * scroll_ / n, bar_w,
                                  track.h * visible_rows() / n},
                                 0.5 * bar_w, t.text_muted);
  }
}

}  // namespace vdfx::ui
