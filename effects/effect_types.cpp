#include "effects/effect_types.h"

#include <algorithm>
#include <stdexcept>

namespace vdfx::effects {

int EffectSpec::dimension() const {
  int n = 0;
  for (const auto& p : params) n += p.size;
  return n;
}

std::vector<double> EffectSpec::neutral() const {
  std::vector<double> v;
  for (const auto& p : params) v.insert(v.end(), static_cast<size_t>(p.size), p.neutral);
  return v;
}

const std::vector<EffectSpec>& all_effect_specs() {
  static const std::vector<EffectSpec> specs = {
      {EffectType::Blur, "blur", {{"sigma_deg", 1, 0.0, 10.0, 0.0}}},
      {EffectType::Tint, "tint", {{"gain", 3, 0.0, 4.0, 1.0}}},
      {EffectType::Exposure, "exposure", {{"stops", 1, -8.0, 8.0, 0.0}}},
      {EffectType::Saturation, "saturation", {{"amount", 1, 0.0, 4.0, 1.0}}},
      {EffectType::Contrast, "contrast", {{"amount", 1, 0.0, 4.0, 1.0}}},
      {EffectType::Vignette,
       "vignette",
       {{"radius_deg", 1, 0.0, 180.0, 180.0}, {"falloff_deg", 1, 0.01, 180.0, 0.01}}},
  };
  return specs;
}

const EffectSpec& effect_spec(EffectType type) {
  return all_effect_specs().at(static_cast<size_t>(type));
}

std::optional<EffectType> effect_type_from_name(std::string_view name) {
  for (const auto& s : all_effect_specs())
    if (s.name == name) return s.type;
  return std::nullopt;
}

std::string_view effect_name(EffectType type) {
  return effect_spec(type).name;
}

Eigen::Vector3d normalize_tint(const Eigen::Vector3d& gain) {
  const double luma = kLumaR * gain.x() + kLumaG * gain.y() + kLumaB * gain.z();
  if (!(luma > 0.0)) return Eigen::Vector3d::Ones();
  return gain / luma;
}

namespace {
double clamp_to(const ParamSpec& p, double v) {
  return std::clamp(v, p.min, p.max);
}
}  // namespace

void StackParams::set(EffectType type, std::span<const double> values) {
  const EffectSpec& spec = effect_spec(type);
  if (static_cast<int>(values.size()) != spec.dimension())
    throw std::invalid_argument("StackParams::set: wrong parameter count for " +
                                std::string(spec.name));
  const ParamSpec& p0 = spec.params[0];
  switch (type) {
    case EffectType::Blur: blur_sigma_deg = clamp_to(p0, values[0]); break;
    case EffectType::Tint:
      tint_gain = normalize_tint(
          {clamp_to(p0, values[0]), clamp_to(p0, values[1]), clamp_to(p0, values[2])});
      break;
    case EffectType::Exposure: exposure_stops = clamp_to(p0, values[0]); break;
    case EffectType::Saturation: saturation = clamp_to(p0, values[0]); break;
    case EffectType::Contrast: contrast = clamp_to(p0, values[0]); break;
    case EffectType::Vignette:
      vignette_radius_deg = clamp_to(p0, values[0]);
      vignette_falloff_deg = clamp_to(spec.params[1], values[1]);
      break;
  }
}

std::vector<double> StackParams::get(EffectType type) const {
  switch (type) {
    case EffectType::Blur: return {blur_sigma_deg};
    case EffectType::Tint: return {tint_gain.x(), tint_gain.y(), tint_gain.z()};
    case EffectType::Exposure: return {exposure_stops};
    case EffectType::Saturation: return {saturation};
    case EffectType::Contrast: return {contrast};
    case EffectType::Vignette: return {vignette_radius_deg, vignette_falloff_deg};
  }
  return {};
}

bool StackParams::is_neutral(EffectType type) const {
  switch (type) {
    case EffectType::Blur: return blur_sigma_deg == 0.0;
    case EffectType::Tint: return tint_gain == Eigen::Vector3d::Ones();
    case EffectType::Exposure: return exposure_stops == 0.0;
    case EffectType::Saturation: return saturation == 1.0;
    case EffectType::Contrast: return contrast == 1.0;
    // A vignette whose black region starts at or beyond 180 degrees touches no direction.
    case EffectType::Vignette: return vignette_radius_deg >= 180.0;
  }
  return true;
}

}  // namespace vdfx::effects
