/// @file
/// @brief The sidecar's `"type": "grain"` entries (shared/guide/flare-grain.md, "Sidecar
/// extension"; docs/sidecar.md, docs/grain.md): reading with every problem reported (pointer
/// and reason), and writing in the documented key order.
///
/// {"type": "grain", "style": "headset" | "surface" | "object_cloud" | "free_cloud",
///  "seed": non-negative integer,
///  "settings": {"refresh_ms", and the style's own: plane_m | sphere_m | sphere_m, shell, count |
///               count, radius_m, height_m}           (optional, each field too),
///  "interpolation": {...}                            (optional, as for any effect),
///  "keyframes": [{"azimuth_deg", "altitude_deg", "frame", "params": {"intensity", "size"}}, ...]}
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "effects/grain.h"

namespace vdfx::io {

inline constexpr const char* kGrainTypeName = "grain";

/// True when an "effects" entry is an object whose "type" is "grain".
bool is_grain_entry(const nlohmann::json& entry);

/// The entry as written: the style's settings all explicit (absent ones were filled with their
/// defaults on reading), so write -> read -> write is byte-identical.
nlohmann::ordered_json grain_to_json(const effects::GrainEffect& grain);

namespace detail {
class Checker;
/// Reads one grain entry at `ptr`, reporting every problem through `c`; keyframe frames are
/// checked against [0, frames) when the video's frame count is known.
void read_grain(Checker& c, const nlohmann::json& entry, const std::string& ptr,
                std::optional<std::int64_t> frames, effects::GrainEffect& out);
}  // namespace detail

}  // namespace vdfx::io
