/// @file
/// @brief Flare entries of the sidecar: reader and writer.
#include "io/sidecar_flare.h"

#include <cmath>
#include <limits>

#include "effects/direction_angle.h"
#include "io/sidecar.h"
#include "io/sidecar_anchor.h"
#include "io/sidecar_checker.h"

namespace vdfx::io {

namespace {

using ordered = nlohmann::ordered_json;
using detail::Checker;
using nlohmann::json;

// Consecutive track samples at least this far apart have no unique great circle between them.
constexpr double kAntipodalDeg = 179.9;

ordered direction_json(const effects::Direction& d) {
  ordered j;
  j["azimuth_deg"] = d.azimuth_deg;
  j["altitude_deg"] = d.altitude_deg;
  return j;
}

ordered light_json(const effects::FlareLight& light) {
  if (const auto* d = std::get_if<effects::Direction>(&light)) return direction_json(*d);
  if (std::holds_alternative<effects::AutoLight>(light)) return "auto";
  ordered track = ordered::array();
  for (const effects::LightSample& s : std::get<std::vector<effects::LightSample>>(light)) {
    ordered j;
    j["frame"] = s.frame;
    j["azimuth_deg"] = s.direction.azimuth_deg;
    j["altitude_deg"] = s.direction.altitude_deg;
    track.push_back(std::move(j));
  }
  return track;
}

/// azimuth_deg and altitude_deg of `obj` (the keyframes' ranges).
void read_direction(Checker& c, const json& obj, const std::string& ptr, effects::Direction& out) {
  if (const json* p = c.member(obj, ptr, "azimuth_deg"))
    if (auto d = c.number(*p, ptr + "/azimuth_deg", {-180.0, 180.0, true, false}))
      out.azimuth_deg = *d;
  if (const json* p = c.member(obj, ptr, "altitude_deg"))
    if (auto d = c.number(*p, ptr + "/altitude_deg", {-90.0, 90.0, false, false}))
      out.altitude_deg = *d;
}

std::string frame_range_text(std::optional<std::int64_t> frames) {
  return frames ? "[0, " + std::to_string(*frames) + ") (video.frames is " +
                      std::to_string(*frames) + ")"
                : std::string("[0, video.frames)");
}

void read_track(Checker& c, const json& arr, const std::string& ptr,
                std::optional<std::int64_t> frames, std::vector<effects::LightSample>& out) {
  if (arr.empty()) {
    c.error(
        ptr,
        "a light track needs at least one {\"frame\", \"azimuth_deg\", \"altitude_deg\"} sample");
    return;
  }
  const std::int64_t hi = frames ? *frames - 1 : std::numeric_limits<std::int64_t>::max();
  std::optional<effects::LightSample> previous;  // the last sample read without a problem
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string sp = ptr + "/" + std::to_string(i);
    const json* obj = c.object(arr[i], sp);
    if (!obj) {
      previous.reset();
      continue;
    }
    c.only_keys(*obj, sp, {"frame", "azimuth_deg", "altitude_deg"});
    effects::LightSample s;
    std::optional<std::int64_t> frame;
    if (const json* p = c.member(*obj, sp, "frame"))
      frame = c.integer(*p, sp + "/frame", 0, hi, frame_range_text(frames));
    const std::size_t before = c.problems();
    read_direction(c, *obj, sp, s.direction);
    const bool direction_ok = c.problems() == before;
    if (frame) s.frame = *frame;
    if (frame && previous && s.frame <= previous->frame)
      c.error(sp + "/frame",
              "frame " + std::to_string(s.frame) + " is not after the previous sample's " +
                  std::to_string(previous->frame) + " (a track's frames strictly increase)");
    if (direction_ok && previous &&
        effects::angle_between_deg(previous->direction, s.direction) >= kAntipodalDeg)
      c.error(sp,
              "this sample and the previous one point in opposite directions: the great circle "
              "between them is not unique (add a sample in between)");
    out.push_back(s);
    if (frame && direction_ok)
      previous = s;
    else
      previous.reset();
  }
}

void read_light(Checker& c, const json& v, const std::string& ptr,
                std::optional<std::int64_t> frames, effects::FlareLight& out) {
  if (v.is_string()) {
    if (v.get<std::string>() == "auto")
      out = effects::AutoLight{};
    else
      c.error(ptr, "unknown light \"" + v.get<std::string>() +
                       "\" (expected \"auto\", a direction object or a track)");
  } else if (v.is_object()) {
    c.only_keys(v, ptr, {"azimuth_deg", "altitude_deg"});
    effects::Direction d;
    read_direction(c, v, ptr, d);
    out = d;
  } else if (v.is_array()) {
    std::vector<effects::LightSample> track;
    read_track(c, v, ptr, frames, track);
    out = std::move(track);
  } else {
    c.error(ptr, std::string(
                     "expected a direction object, a track (array of {\"frame\", \"azimuth_deg\", "
                     "\"altitude_deg\"}) or \"auto\", found ") +
                     detail::type_name(v));
  }
}

void read_settings(Checker& c, const json& v, const std::string& ptr, effects::FlareSettings& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"fade_deg", "ramp_deg", "rings", "plane_m"});
  std::optional<double> fade, ramp;
  if (const json* p = c.member(*obj, ptr, "fade_deg", false))
    if ((fade = c.number(*p, ptr + "/fade_deg",
                         {effects::kFlareFadeMinDeg, effects::kFlareFadeMaxDeg, true, false})))
      out.fade_deg = *fade;
  if (const json* p = c.member(*obj, ptr, "ramp_deg", false))
    if ((ramp = c.number(*p, ptr + "/ramp_deg", {0.0, effects::kFlareRampMaxDeg, false, false})))
      out.ramp_deg = *ramp;
  if (const json* p = c.member(*obj, ptr, "rings", false))
    if (auto i = c.integer(*p, ptr + "/rings", 0, effects::kMaxFlareRings,
                           "[0, " + std::to_string(effects::kMaxFlareRings) + "]"))
      out.rings = static_cast<int>(*i);
  if (const json* p = c.member(*obj, ptr, "plane_m", false))
    if (auto d = c.number(*p, ptr + "/plane_m",
                          {effects::kFlarePlaneMinM, effects::kFlarePlaneMaxM, false, false}))
      out.plane_m = *d;
  // Only when both values are fine on their own (or defaults): otherwise that is the problem.
  const bool fade_ok = fade || !obj->contains("fade_deg"),
             ramp_ok = ramp || !obj->contains("ramp_deg");
  if (fade_ok && ramp_ok && out.fade_deg + 0.5 * out.ramp_deg > effects::kFlareFadeOuterMaxDeg)
    c.error(
        ptr + (obj->contains("ramp_deg") ? "/ramp_deg" : "/fade_deg"),
        "fade_deg + ramp_deg / 2 = " + detail::num(out.fade_deg + 0.5 * out.ramp_deg) +
            " exceeds " + detail::num(effects::kFlareFadeOuterMaxDeg) +
            " (the flare must vanish before the light leaves the half-space in front of the gaze)");
}

}  // namespace

bool is_flare_entry(const nlohmann::json& entry) {
  return detail::has_type(entry, kFlareTypeName);
}

nlohmann::ordered_json flare_to_json(const effects::FlareEffect& f) {
  ordered e;
  e["type"] = kFlareTypeName;
  e["style"] = std::string(effects::flare_style_name(f.style));
  detail::write_anchor(e, f.anchor);
  e["light"] = light_json(f.light);
  ordered s;
  s["fade_deg"] = f.settings.fade_deg;
  s["ramp_deg"] = f.settings.ramp_deg;
  s["rings"] = f.settings.rings;
  s["plane_m"] = f.settings.plane_m;
  e["settings"] = std::move(s);
  if (f.interpolation) e["interpolation"] = interpolation_to_json(*f.interpolation);
  e["keyframes"] = scalar_keyframes_to_json(f.keyframes, {&effects::kFlareIntensitySpec, 1});
  return e;
}

namespace detail {

void read_flare(Checker& c, const json& entry, const std::string& ptr,
                std::optional<std::int64_t> frames, effects::FlareEffect& out) {
  // is_flare_entry chose this reader: entry is an object with "type": "flare".
  c.only_keys(entry, ptr,
              {"type", "style", "light", "settings", "anchor", "interpolation", "keyframes"});
  if (const json* p = c.member(entry, ptr, "style")) {
    if (auto s = c.string(*p, ptr + "/style")) {
      if (auto style = effects::flare_style_from_name(*s))
        out.style = *style;
      else
        c.error(ptr + "/style",
                "unknown flare style \"" + excerpt(*s) + "\" (expected headset or directional)");
    }
  }
  // Missing settings take the style's defaults (plane_m differs between the styles).
  out.settings = effects::default_flare_settings(out.style);
  if (const json* p = c.member(entry, ptr, "light"))
    read_light(c, *p, ptr + "/light", frames, out.light);
  if (const json* p = c.member(entry, ptr, "settings", false))
    read_settings(c, *p, ptr + "/settings", out.settings);
  read_anchor(c, entry, ptr, out.anchor);
  read_interpolation_override(c, entry, ptr, out.interpolation);
  if (const json* p = c.member(entry, ptr, "keyframes"))
    detail::read_scalar_keyframes(c, *p, ptr + "/keyframes", frames,
                                  {&effects::kFlareIntensitySpec, 1}, out.keyframes);
}

}  // namespace detail

}  // namespace vdfx::io
