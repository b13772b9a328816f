/// @file
/// @brief The one place for the toolkit's colours, sizes and spacing.
///
/// Sizes are in panel pixels. Panels are drawn at kPixelsPerMetre (1000 px per 0.25 m), so
/// 1 px = 0.25 mm; see docs/ui.md for the angular sizes these give at arm's length.
#pragma once

#include "ui/colour.h"

namespace vdfx::ui {

/// Panel texture resolution every panel uses unless told otherwise: 1000 px per 0.25 m.
inline constexpr double kPixelsPerMetre = 4000.0;

struct Theme {
  // Colours (straight alpha).
  Rgba panel_bg;            //!< dark translucent panel background
  Rgba panel_border;        //!< thin outline so the panel reads against bright video
  Rgba surface;             //!< resting widget background
  Rgba surface_hover;       //!< widget under the pointer
  Rgba surface_pressed;     //!< widget held by the trigger
  Rgba track;               //!< empty part of slider tracks, pad and plot grid
  Rgba text;                //!< primary text
  Rgba text_muted;          //!< secondary text (value units, axis labels)
  Rgba accent;              //!< filled track, thumbs, toggle on, focus ring
  Rgba selection;           //!< selected menu row (primary text sits on it)
  Rgba keyframe;            //!< keyframe markers
  Rgba keyframe_highlight;  //!< keyframes at the current frame / selected
  Rgba playhead;            //!< timeline / plot playhead
  Rgba plot_line;           //!< plotted values
  // Sizes (pixels).
  double corner_radius;  //!< panel and widget corners
  double padding;        //!< inside panels and widgets
  double gap;            //!< between stacked widgets
  double focus_width;    //!< focus ring stroke
  double row_height;     //!< buttons, menu rows, toggles
  int font_title;        //!< bold headings, pixel height (ascent - descent)
  int font_body;         //!< labels, buttons, menu items
  int font_small;        //!< values, axis labels: the smallest text the toolkit draws

  static const Theme& dark();
};

}  // namespace vdfx::ui
