/// @file
/// @brief draw_titled_card.
#include "ui/card.h"

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

void draw_titled_card(DrawContext& ctx, const Rect& r, const std::string& title) {
  const Theme& t = ctx.theme;
  ctx.canvas.fill_rounded_rect(r, t.corner_radius, t.surface);
  ctx.canvas.text(*ctx.fonts.regular, t.font_body, title,
                  {r.x + t.padding, r.y + 8, r.w - 2 * t.padding, 56}, Align::Left, t.text);
}

}  // namespace vdfx::ui
