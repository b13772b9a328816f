/// @file
/// @brief Grain entries of the sidecar: reader and writer.
#include "io/sidecar_grain.h"

#include <limits>

#include "io/sidecar.h"
#include "io/sidecar_anchor.h"
#include "io/sidecar_checker.h"

namespace vdfx::io {

namespace {

using ordered = nlohmann::ordered_json;
using detail::Checker;
using nlohmann::json;

std::string style_list() {
  std::string s;
  for (effects::GrainStyle st : effects::kGrainStyles)
    s += (s.empty() ? "" : ", ") + std::string(effects::grain_style_name(st));
  return s;
}

std::string settings_list(std::optional<effects::GrainStyle> style) {
  std::string s;
  for (const effects::GrainSettingSpec& spec : effects::grain_setting_specs())
    if (!style || effects::grain_style_has_setting(*style, spec.id))
      s += (s.empty() ? "" : ", ") + std::string(spec.name);
  return s;
}

/// Settings: known names only; a setting of another style is named as such (it would be
/// silently ignored otherwise); each value in its range, count a whole number.
void read_settings(Checker& c, const json& v, const std::string& ptr,
                   std::optional<effects::GrainStyle> style, effects::GrainSettings& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  for (const auto& [key, value] : obj->items()) {
    const std::string kp = ptr + "/" + excerpt(json_pointer_token(key));
    const effects::GrainSettingSpec* spec = nullptr;
    for (const auto& s : effects::grain_setting_specs())
      if (s.name == key) spec = &s;
    if (!spec) {
      c.error(kp,
              "unknown field \"" + excerpt(key) + "\" (expected: " + settings_list(style) + ")");
      continue;
    }
    if (style && !effects::grain_style_has_setting(*style, spec->id)) {
      c.error(kp, "\"" + key + "\" is not a setting of style " +
                      std::string(effects::grain_style_name(*style)) +
                      " (its settings: " + settings_list(style) + ")");
      continue;
    }
    if (spec->integer) {
      const auto lo = static_cast<std::int64_t>(spec->min),
                 hi = static_cast<std::int64_t>(spec->max);
      if (auto i = c.integer(value, kp, lo, hi,
                             "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]"))
        out.set(spec->id, static_cast<double>(*i));
    } else if (auto d = c.number(value, kp, {spec->min, spec->max, spec->min_open, false})) {
      out.set(spec->id, *d);
    }
  }
}

}  // namespace

bool is_grain_entry(const nlohmann::json& entry) {
  return detail::has_type(entry, kGrainTypeName);
}

nlohmann::ordered_json grain_to_json(const effects::GrainEffect& g) {
  ordered e;
  e["type"] = kGrainTypeName;
  e["style"] = std::string(effects::grain_style_name(g.style));
  detail::write_anchor(e, g.anchor);
  e["seed"] = g.seed;
  ordered s = ordered::object();
  for (effects::GrainSetting id : effects::grain_style_settings(g.style)) {
    const effects::GrainSettingSpec& spec = effects::grain_setting_spec(id);
    if (spec.integer)
      s[std::string(spec.name)] = static_cast<std::int64_t>(g.settings.get(id));
    else
      s[std::string(spec.name)] = g.settings.get(id);
  }
  e["settings"] = std::move(s);
  if (g.interpolation) e["interpolation"] = interpolation_to_json(*g.interpolation);
  e["keyframes"] = scalar_keyframes_to_json(g.keyframes, effects::grain_param_specs());
  return e;
}

namespace detail {

void read_grain(Checker& c, const json& entry, const std::string& ptr,
                std::optional<std::int64_t> frames, effects::GrainEffect& out) {
  // is_grain_entry chose this reader: entry is an object with "type": "grain".
  c.only_keys(entry, ptr,
              {"type", "style", "seed", "settings", "anchor", "interpolation", "keyframes"});
  std::optional<effects::GrainStyle> style;
  if (const json* p = c.member(entry, ptr, "style")) {
    if (auto s = c.string(*p, ptr + "/style")) {
      if ((style = effects::grain_style_from_name(*s)))
        out.style = *style;
      else
        c.error(ptr + "/style",
                "unknown grain style \"" + excerpt(*s) + "\" (expected: " + style_list() + ")");
    }
  }
  if (const json* p = c.member(entry, ptr, "seed"))
    if (auto i =
            c.integer(*p, ptr + "/seed", 0, std::numeric_limits<std::int64_t>::max(), "[0, 2^63)"))
      out.seed = static_cast<std::uint64_t>(*i);
  out.settings = effects::GrainSettings(out.style);
  if (const json* p = c.member(entry, ptr, "settings", false))
    read_settings(c, *p, ptr + "/settings", style, out.settings);
  read_anchor(c, entry, ptr, out.anchor);
  read_interpolation_override(c, entry, ptr, out.interpolation);
  if (const json* p = c.member(entry, ptr, "keyframes"))
    detail::read_scalar_keyframes(c, *p, ptr + "/keyframes", frames, effects::grain_param_specs(),
                                  out.keyframes);
}

}  // namespace detail

}  // namespace vdfx::io
