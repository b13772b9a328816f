/// @file
/// @brief The auto lights of a published film: the page cannot run the auto-light tracker on the
/// video's pixels cheaply, so `vdfx publish` runs vdfx's own (effects/auto_light.h) over every
/// frame and writes each frame's tracked light into lights.json; the module's FlareSet takes
/// them instead of observing frames (docs/publish.md, "Auto lights").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "io/sidecar.h"

namespace vdfx::app {

/// The file publish writes the lights into, beside player.json.
inline constexpr const char* kLightsFile = "lights.json";

/// Whether some flare of the sidecar finds its light in the video ("light": "auto").
bool uses_auto_light(const io::Sidecar& sidecar);

/// lights.json's object: {"format": "vdfx.lights", "version": 1, "frames": N, "lights": [...]},
/// entry f frame f's tracked light ({"azimuth_deg", "altitude_deg"}) or null, from every frame of
/// `video` (the published one: the page's pixels) decoded in order as vdfx render decodes it
/// (RGB float). io::InputError naming the
/// video when a frame cannot be decoded.
nlohmann::ordered_json track_auto_lights(const std::filesystem::path& video,
                                         const io::Sidecar& sidecar);

}  // namespace vdfx::app
