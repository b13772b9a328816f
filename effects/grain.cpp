/// @file
/// @brief Grain styles, settings table, parameter specs and the refresh clock.
#include "effects/grain.h"

#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

std::string_view grain_style_name(GrainStyle style) {
  switch (style) {
    case GrainStyle::Headset: return "headset";
    case GrainStyle::Surface: return "surface";
    case GrainStyle::ObjectCloud: return "object_cloud";
    case GrainStyle::FreeCloud: return "free_cloud";
  }
  return "surface";
}

std::optional<GrainStyle> grain_style_from_name(std::string_view name) {
  for (GrainStyle s : kGrainStyles)
    if (grain_style_name(s) == name) return s;
  return std::nullopt;
}

const std::array<GrainSettingSpec, kGrainSettingCount>& grain_setting_specs() {
  // Ranges: refresh at least 1 ms (below any display's frame period) and at most a minute; the
  // plane no nearer than 1 cm; distances and sizes within what a room or a 360 scene holds.
  static const std::array<GrainSettingSpec, kGrainSettingCount> specs = {{
      {GrainSetting::RefreshMs, "refresh_ms", 1.0, 60000.0, false, false, 20.0},
      {GrainSetting::PlaneM, "plane_m", 0.01, 100.0, false, false, 0.05},
      {GrainSetting::SphereM, "sphere_m", 0.1, 1000.0, false, false, 10.0},
      {GrainSetting::Shell, "shell", 1.0, 4.0, true, false, 1.1},
      {GrainSetting::Count, "count", 1.0, 1000000.0, false, true, 1000000.0},
      {GrainSetting::RadiusM, "radius_m", 0.1, 100.0, false, false, 2.0},
      {GrainSetting::HeightM, "height_m", 0.1, 100.0, false, false, 3.0},
  }};
  return specs;
}

const GrainSettingSpec& grain_setting_spec(GrainSetting id) {
  return grain_setting_specs()[static_cast<std::size_t>(id)];
}

std::span<const GrainSetting> grain_style_settings(GrainStyle style) {
  using S = GrainSetting;
  static const std::array<S, 2> headset{S::RefreshMs, S::PlaneM};
  static const std::array<S, 2> surface{S::RefreshMs, S::SphereM};
  static const std::array<S, 4> object_cloud{S::RefreshMs, S::SphereM, S::Shell, S::Count};
  static const std::array<S, 4> free_cloud{S::RefreshMs, S::Count, S::RadiusM, S::HeightM};
  switch (style) {
    case GrainStyle::Headset: return headset;
    case GrainStyle::Surface: return surface;
    case GrainStyle::ObjectCloud: return object_cloud;
    case GrainStyle::FreeCloud: return free_cloud;
  }
  return surface;
}

bool grain_style_has_setting(GrainStyle style, GrainSetting id) {
  for (GrainSetting s : grain_style_settings(style))
    if (s == id) return true;
  return false;
}

double grain_setting_default(GrainStyle style, GrainSetting id) {
  if (style == GrainStyle::ObjectCloud && id == GrainSetting::SphereM) return 2.0;
  return grain_setting_spec(id).default_value;
}

GrainSettings::GrainSettings() {
  for (const GrainSettingSpec& s : grain_setting_specs()) set(s.id, s.default_value);
}

GrainSettings::GrainSettings(GrainStyle style) {
  for (const GrainSettingSpec& s : grain_setting_specs())
    set(s.id, grain_setting_default(style, s.id));
}

const std::vector<ParamSpec>& grain_param_specs() {
  static const std::vector<ParamSpec> specs = {{"intensity", 1, 0.0, 1.0, 0.0},
                                               {"size", 1, 0.25, 4.0, 1.0}};
  return specs;
}

std::int64_t grain_refresh_index(std::int64_t display_time_ns, double refresh_ms) {
  if (!(refresh_ms > 0.0) || !std::isfinite(refresh_ms))
    throw std::invalid_argument("grain_refresh_index: refresh_ms must be positive");
  // Whole nanoseconds, so the boundaries are exact multiples and integer division decides.
  const auto period = static_cast<std::int64_t>(std::llround(refresh_ms * 1.0e6));
  const std::int64_t q = display_time_ns / period;
  return (display_time_ns % period < 0) ? q - 1 : q;  // floor for times before 0
}

}  // namespace vdfx::effects
