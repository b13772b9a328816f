/// @file
/// @brief The panels' setting actions: the flare's style and light, the grain's style, the chosen
/// values and the effect's own interpolation (each one undo step, through the document); what
/// the views panel shows and whether the timeline is locked (no undo: not the document's).
#include <cmath>
#include <string>

#include "app/editor/editor.h"

namespace vdfx::app {

void Editor::set_flare_style(effects::FlareStyle style) {
  doc_.set_flare_style(style);
  say(std::string("flare style ") + std::string(effects::flare_style_name(style)));
}

void Editor::set_light_here() {
  // A fixed light is a direction of the flare's anchor's frame (effects/flare_set.h).
  doc_.set_flare_light(doc_.anchor_frames(EditTarget::flare()).apply(view_, play_.frame));
  say("flare light set at az " + std::to_string(static_cast<int>(std::lround(view_.azimuth_deg))) +
      " alt " + std::to_string(static_cast<int>(std::lround(view_.altitude_deg))));
}

void Editor::set_auto_light(bool on) {
  if (!on) return set_light_here();
  doc_.set_flare_light(effects::AutoLight{});
  say("flare light: the brightest region of each frame");
}

void Editor::set_grain_style(effects::GrainStyle style) {
  doc_.set_grain_style(style);
  say(std::string("grain style ") + std::string(effects::grain_style_name(style)));
}

void Editor::set_chosen_params(std::vector<double> params) {
  doc_.set_params(effect_, std::move(params));
  sync_pending();
}

void Editor::set_widget_values(std::vector<double> values) {
  if (selected_)
    set_selected_params(std::move(values));
  else
    set_chosen_params(std::move(values));
}

void Editor::set_exponent(double exponent) {
  auto s = doc_.interpolation(effect_);
  s.exponent = exponent;
  doc_.set_interpolation(effect_, s);
}

void Editor::set_time_scale_deg_per_s(double deg_per_s) {
  auto s = doc_.interpolation(effect_);
  s.time_scale = effects::time_scale_from_deg_per_s(deg_per_s);
  doc_.set_interpolation(effect_, s);
}

void Editor::lock_timeline(bool locked) {
  views_.timeline_locked = locked;
  panels_.lock_timeline(locked);
  show();
}

void Editor::show_track_plot(bool on) {
  views_.track_plot = on;
}

void Editor::show_minimap(bool on) {
  views_.minimap = on;
}

}  // namespace vdfx::app
