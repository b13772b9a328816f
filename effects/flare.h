/// @file
/// @brief A lens-flare effect as the sidecar stores it: style, light source, settings, intensity
/// keyframes (shared/guide/flare-grain.md, "Lens flare"; docs/flare.md).
///
/// A flare is not one of the six stack effects: it is a world-space layer drawn after the effect
/// stack, so it has its own type instead of an EffectType. Its only keyframed parameter is
/// `intensity` (0..4, neutral 0), interpolated with the same spatial-keyframe RBF as the stack
/// effects; several flares may coexist in one sidecar, each with its own keyframes.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

#include "effects/coords.h"
#include "effects/effect_types.h"
#include "effects/keyframe.h"

namespace vdfx::effects {

/// Where the flare's rendering plane sits (docs/flare.md, "Geometry").
enum class FlareStyle {
  Headset,      //!< plane perpendicular to the gaze at plane_m (default 5 cm), anchored to the head
  Directional,  //!< plane perpendicular to the light at plane_m (default 100 m), near the light
};

std::string_view flare_style_name(FlareStyle style);
std::optional<FlareStyle> flare_style_from_name(std::string_view name);

/// One sample of a light track: the light's direction at a video frame.
struct LightSample {
  std::int64_t frame = 0;
  Direction direction;
  bool operator==(const LightSample&) const = default;
};

/// The light is found in each video frame (effects/auto_light.h).
struct AutoLight {
  bool operator==(const AutoLight&) const = default;
};

/// A fixed direction, a time track (strictly increasing frames, interpolated along the great
/// circle between samples, held beyond its ends), or `auto`.
using FlareLight = std::variant<Direction, std::vector<LightSample>, AutoLight>;

/// Settings of one flare; the sidecar's "settings" object (every field optional there).
struct FlareSettings {
  double fade_deg = 15.0;  //!< the flare fades out around this angle between gaze and light
  double ramp_deg = 5.0;   //!< width of the smooth fade, centred on fade_deg
  int rings = 6;           //!< number of rings, 0..kMaxFlareRings
  double plane_m = 100.0;  //!< distance of the rendering plane (style default: 0.05 or 100)
  bool operator==(const FlareSettings&) const = default;
};

/// The defaults of a style (plane_m 0.05 m for headset, 100 m for directional).
FlareSettings default_flare_settings(FlareStyle style);

/// Accepted ranges (the sidecar reader and the geometry agree on these).
inline constexpr int kMaxFlareRings = 16;
inline constexpr double kFlareFadeMinDeg = 0.0;  //!< exclusive
inline constexpr double kFlareFadeMaxDeg = 80.0;
inline constexpr double kFlareRampMaxDeg = 40.0;  //!< ramp is in [0, this]
/// fade + ramp/2 must stay below this, so the light is in front of the gaze (g . l > 0) whenever
/// the flare is visible: the headset style intersects the light's ray with the gaze plane.
inline constexpr double kFlareFadeOuterMaxDeg = 85.0;
inline constexpr double kFlarePlaneMinM = 0.01;
inline constexpr double kFlarePlaneMaxM = 10000.0;

/// The keyframed parameter: intensity multiplies the whole flare.
inline constexpr ParamSpec kFlareIntensitySpec{"intensity", 1, 0.0, 4.0, 0.0};

struct FlareEffect {
  FlareStyle style = FlareStyle::Directional;
  FlareLight light = Direction{};
  FlareSettings settings;
  std::optional<InterpolationSettings> interpolation;  //!< overrides the file's default
  std::vector<Keyframe> keyframes;                     //!< params: {intensity}
  Anchor anchor = {};  //!< the frame the keyframe directions are in (effects/anchor.h)
  bool operator==(const FlareEffect&) const = default;
};

}  // namespace vdfx::effects
