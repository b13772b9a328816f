/// @file
/// @brief Shared drawing helpers of widget.h.
#include "ui/widget.h"

#include <cstdio>

#include "ui/canvas.h"
#include "ui/theme.h"

namespace vdfx::ui {

void draw_widget_frame(DrawContext& ctx, const Widget& w, const Rect& r) {
  const Theme& t = ctx.theme;
  Rgba bg = t.surface;
  if (w.hovered()) bg = t.surface_hover;
  if (w.pressed()) bg = t.surface_pressed;
  ctx.canvas.fill_rounded_rect(r, t.corner_radius, bg);
  if (w.pressed()) ctx.canvas.stroke_rounded_rect(r, t.corner_radius, 2.0, t.accent);
  if (w.focused()) ctx.canvas.stroke_rounded_rect(r, t.corner_radius, t.focus_width, t.accent);
}

std::string format_value(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

}  // namespace vdfx::ui
