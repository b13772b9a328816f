/// @file
/// @brief The sidecar's `"type": "flare"` entries (shared/guide/flare-grain.md, "Sidecar
/// extension"; docs/sidecar.md): reading with every problem reported (pointer and reason), and
/// writing in the documented key order.
///
/// {"type": "flare", "style": "headset" | "directional",
///  "light": {"azimuth_deg", "altitude_deg"} | [{"frame", "azimuth_deg", "altitude_deg"}, ...] |
///  "auto", "settings": {"fade_deg", "ramp_deg", "rings", "plane_m"}   (optional, each field too),
///  "interpolation": {...}                                      (optional, as for any effect),
///  "keyframes": [{"azimuth_deg", "altitude_deg", "frame", "params": {"intensity"}}, ...]}
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "effects/flare.h"

namespace vdfx::io {

inline constexpr const char* kFlareTypeName = "flare";

/// True when an "effects" entry is an object whose "type" is "flare".
bool is_flare_entry(const nlohmann::json& entry);

/// The entry as written: every setting explicit (the style's defaults filled in on reading), so
/// write -> read -> write is byte-identical.
nlohmann::ordered_json flare_to_json(const effects::FlareEffect& flare);

namespace detail {
class Checker;
/// Reads one flare entry at `ptr`, reporting every problem through `c`; keyframe and track frames
/// are checked against [0, frames) when the video's frame count is known.
void read_flare(Checker& c, const nlohmann::json& entry, const std::string& ptr,
                std::optional<std::int64_t> frames, effects::FlareEffect& out);
}  // namespace detail

}  // namespace vdfx::io
