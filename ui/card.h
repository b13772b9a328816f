/// @file
/// @brief A titled card: the rounded surface with a title line that the display widgets
/// (Minimap, Plot) draw their content on.
#pragma once

#include <string>

#include "ui/rect.h"
#include "ui/widget.h"

namespace vdfx::ui {

/// Fills `r` with the theme's rounded surface and writes `title` in its top-left corner, in the
/// body font. The content goes below the title (each widget keeps its own title height).
void draw_titled_card(DrawContext& ctx, const Rect& r, const std::string& title);

}  // namespace vdfx::ui
