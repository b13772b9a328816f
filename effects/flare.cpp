/// @file
/// @brief Flare style names and per-style defaults.
#include "effects/flare.h"

namespace vdfx::effects {

std::string_view flare_style_name(FlareStyle style) {
  return style == FlareStyle::Headset ? "headset" : "directional";
}

std::optional<FlareStyle> flare_style_from_name(std::string_view name) {
  if (name == "headset") return FlareStyle::Headset;
  if (name == "directional") return FlareStyle::Directional;
  return std::nullopt;
}

FlareSettings default_flare_settings(FlareStyle style) {
  FlareSettings s;
  // 5 cm in front of the eyes is the study's headset plane; 100 m is far enough that the
  // directional flare has the light's own (near zero) disparity (docs/flare.md, "Stereo").
  s.plane_m = style == FlareStyle::Headset ? 0.05 : 100.0;
  return s;
}

}  // namespace vdfx::effects
