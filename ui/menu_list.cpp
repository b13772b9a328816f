/// @file
/// @brief MenuList.
#include "ui/menu_list.h"

#include <algorithm>
#include <cmath>

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
constexpr double kInset = 8.0;  // rows sit this far inside the frame
}

MenuList::MenuList(std::string id, std::vector<std::string> items, int selected, double row_height,
                   int columns)
    : Widget(std::move(id)),
      items_(std::move(items)),
      selected_(0),
      row_h_(row_height),
      columns_(std::max(1, columns)) {
  select(selected);
}

int MenuList::rows() const {
  return (static_cast<int>(items_.size()) + columns_ - 1) / columns_;
}

double MenuList::bar_width() const {
  return rows() > visible_rows() ? 14.0 : 0.0;
}

Rect MenuList::cell(int index) const {
  const Rect r = rect();
  const double w = (r.w - 2 * kInset - bar_width()) / columns_;
  return {r.x + kInset + (index % columns_) * w,
          r.y + kInset + (index / columns_ - scroll_) * row_h_, w, row_h_};
}

void MenuList::set_items(std::vector<std::string> items) {
  set(items_, items);
  select(selected_);
}

int MenuList::visible_rows() const {
  return std::max(1, static_cast<int>(std::floor((rect().h - 2 * kInset) / row_h_)));
}

void MenuList::set_scroll(int first) {
  const int max_first = std::max(0, rows() - visible_rows());
  set(scroll_, std::clamp(first, 0, max_first));
}

void MenuList::select(int index) {
  if (items_.empty()) return set(selected_, 0);
  set(selected_, std::clamp(index, 0, static_cast<int>(items_.size()) - 1));
  if (rect().empty()) return;  // scrolled into view once laid out
  const int row = selected_ / columns_;
  if (row < scroll_) set_scroll(row);
  if (row >= scroll_ + visible_rows()) set_scroll(row - visible_rows() + 1);
}

int MenuList::row_at(glm::dvec2 p) const {
  if (!rect().contains(p)) return -1;
  const int row = static_cast<int>(std::floor((p.y - rect().y - kInset) / row_h_));
  if (row < 0 || row >= visible_rows()) return -1;
  const double w = (rect().w - 2 * kInset - bar_width()) / columns_;
  const int col = static_cast<int>(std::floor((p.x - rect().x - kInset) / w));
  if (col < 0 || col >= columns_) return -1;
  const int index = (scroll_ + row) * columns_ + col;
  return index < static_cast<int>(items_.size()) ? index : -1;
}

void MenuList::hover_at(glm::dvec2 p) {
  const int row = row_at(p);
  if (row == hover_row_) return;
  // Only the items losing and gaining the highlight change (1 px more for anti-aliasing).
  auto band = [&](int index) {
    const Rect c = cell(index);
    return Rect{c.x - 1.0, c.y - 1.0, c.w + 2.0, c.h + 2.0};
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
  const int n = static_cast<int>(items_.size());
  if (d.y != 0 && selected_ - d.y * columns_ >= 0 && selected_ - d.y * columns_ < n)
    select(selected_ - d.y * columns_);  // up = the item above
  if (d.x != 0 && columns_ > 1) select(selected_ + d.x);
}

void MenuList::thumbstick(glm::dvec2 stick, double dt) {
  if (std::abs(stick.y) < 0.5) {
    held_ = 0.0;
    return;
  }
  held_ += dt;
  for (; held_ >= kRepeatSeconds; held_ -= kRepeatSeconds) step({0, stick.y > 0 ? 1 : -1});
}

void MenuList::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Rect r = rect();
  ctx.canvas.fill_rounded_rect(r, t.corner_radius, t.surface);
  if (focused()) ctx.canvas.stroke_rounded_rect(r, t.corner_radius, t.focus_width, t.accent);
  const double bar_w = bar_width();
  const bool scrolls = bar_w > 0.0;
  ctx.canvas.push_clip(r.inset(kInset));
  const int first = scroll_ * columns_;
  const int end = std::min(static_cast<int>(items_.size()), (scroll_ + visible_rows()) * columns_);
  for (int i = first; i < end; ++i) {
    const Rect c = cell(i);
    const Rect rr{c.x, c.y, c.w - 4.0, c.h - 4.0};
    if (i == selected_)
      ctx.canvas.fill_rounded_rect(rr, t.corner_radius - 4, t.selection);
    else if (i == hover_row_ && hovered())
      ctx.canvas.fill_rounded_rect(rr, t.corner_radius - 4, t.surface_hover);
    ctx.canvas.text(*ctx.fonts.regular, t.font_body, items_[static_cast<size_t>(i)],
                    rr.inset(t.padding - kInset, 0), Align::Left, t.text);
  }
  ctx.canvas.pop_clip();
  if (scrolls) {
    const Rect track{r.right() - kInset - bar_w, r.y + kInset, bar_w, r.h - 2 * kInset};
    ctx.canvas.fill_rounded_rect(track, 0.5 * bar_w, t.track);
    const double n = static_cast<double>(rows());
    ctx.canvas.fill_rounded_rect(
        {track.x, track.y + track.h * scroll_ / n, bar_w, track.h * visible_rows() / n},
        0.5 * bar_w, t.text_muted);
  }
}

}  // namespace vdfx::ui
