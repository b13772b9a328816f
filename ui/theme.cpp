/// @file
/// @brief The dark theme. Colour pairs that carry text are checked for WCAG contrast in
/// tests/ui/theme_test.cpp, over both a black and a white backdrop (video shows through).
#include "ui/theme.h"

namespace vdfx::ui {

const Theme& Theme::dark() {
  static const Theme t{
      .panel_bg = Rgba::hex(0x14171d, 0.90f),
      .panel_border = Rgba::hex(0x4a5366, 1.0f),
      .surface = Rgba::hex(0x262b35),
      .surface_hover = Rgba::hex(0x343b49),
      .surface_pressed = Rgba::hex(0x1a1e26),
      .track = Rgba::hex(0x3d4554),
      .text = Rgba::hex(0xf1f4f9),
      .text_muted = Rgba::hex(0xaab3c2),
      .accent = Rgba::hex(0x4c9aff),
      .selection = Rgba::hex(0x1f5fd1),
      .keyframe = Rgba::hex(0xd9a21b),
      .keyframe_highlight = Rgba::hex(0xffd54a),
      .playhead = Rgba::hex(0xff5468),
      .plot_line = Rgba::hex(0x5fd3a4),
      .corner_radius = 16.0,
      .padding = 24.0,
      .gap = 16.0,
      .focus_width = 5.0,
      .row_height = 76.0,
      .font_title = 48,
      .font_body = 40,
      .font_small = 34,
  };
  return t;
}

}  // namespace vdfx::ui
