/// @file
/// @brief Drawing of Button, Toggle and Label.
#include "ui/button.h"

#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
void draw_icon(Canvas& c, Icon icon, glm::dvec2 centre, double size, Rgba col) {
  const double h = 0.5 * size;
  if (icon == Icon::Play) {
    const glm::dvec2 tri[3] = {centre + glm::dvec2(-0.8 * h, -h), centre + glm::dvec2(-0.8 * h, h),
                               centre + glm::dvec2(h, 0)};
    c.fill_convex(tri, col);
  } else if (icon == Icon::Pause) {
    const double bw = 0.36 * size;
    c.fill_rounded_rect({centre.x - h, centre.y - h, bw, size}, 3.0, col);
    c.fill_rounded_rect({centre.x + h - bw, centre.y - h, bw, size}, 3.0, col);
  }
}
}  // namespace

void Button::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  draw_widget_frame(ctx, *this, rect());
  const Rgba col = enabled() ? t.text : t.text_muted;
  const int px = t.font_body;
  const double icon_size = 0.7 * px;
  if (icon_ == Icon::None) {
    ctx.canvas.text(*ctx.fonts.regular, px, label_, rect().inset(t.padding, 0), Align::Centre, col);
    return;
  }
  const double text_w =
      label_.empty() ? 0.0 : ctx.canvas.text_width(*ctx.fonts.regular, px, label_);
  const double gap = label_.empty() ? 0.0 : 0.4 * px;
  const double total = icon_size + gap + text_w;
  const double x0 = rect().centre().x - 0.5 * total;
  draw_icon(ctx.canvas, icon_, {x0 + 0.5 * icon_size, rect().centre().y}, icon_size, col);
  if (!label_.empty())
    ctx.canvas.text(*ctx.fonts.regular, px, label_,
                    {x0 + icon_size + gap, rect().y, text_w + 2.0, rect().h}, Align::Left, col);
}

void Toggle::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  draw_widget_frame(ctx, *this, rect());
  const double track_h = 44.0, track_w = 88.0;
  const Rect track{rect().right() - t.padding - track_w, rect().centre().y - 0.5 * track_h, track_w,
                   track_h};
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, label_,
                  {rect().x + t.padding, rect().y, track.x - rect().x - 2 * t.padding, rect().h},
                  Align::Left, enabled() ? t.text : t.text_muted);
  ctx.canvas.fill_rounded_rect(track, 0.5 * track_h, on_ ? t.accent : t.track);
  const double r = 0.5 * track_h - 5.0;
  const double cx = on_ ? track.right() - 0.5 * track_h : track.x + 0.5 * track_h;
  ctx.canvas.fill_circle({cx, track.centre().y}, r, t.text);
}

void Label::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  const Font& font = role_ == Role::Title ? *ctx.fonts.bold : *ctx.fonts.regular;
  const int px = role_ == Role::Title  ? t.font_title
                 : role_ == Role::Body ? t.font_body
                                       : t.font_small;
  ctx.canvas.text(font, px, text_, rect(), align_, muted_ ? t.text_muted : t.text);
}

}  // namespace vdfx::ui
