/// @file
/// @brief A spatial keyframe and the interpolation settings of the contract.
#pragma once

#include <cstdint>
#include <vector>

#include "effects/coords.h"
#include "effects/effect_types.h"

namespace vdfx::effects {

/// An effect's parameters at (azimuth, altitude, frame).
struct Keyframe {
  Direction direction;
  std::int64_t frame = 0;      //!< 0-based video frame index
  std::vector<double> params;  //!< flat vector laid out as the effect's EffectSpec
  bool operator==(const Keyframe&) const = default;
};

inline bool operator==(const Direction& a, const Direction& b) {
  return a.azimuth_deg == b.azimuth_deg && a.altitude_deg == b.altitude_deg;
}

/// Contract: phi(d) = d^exponent; dt = |f_v - f_k| * (24 / fps) * time_scale.
struct InterpolationSettings {
  double exponent = 1.0;
  double time_scale = 1.0;
  bool operator==(const InterpolationSettings&) const = default;
};

/// One effect's keyframe set as stored in a sidecar.
struct EffectTrack {
  EffectType type = EffectType::Exposure;
  std::optional<InterpolationSettings> interpolation;  //!< overrides the file's default
  std::vector<Keyframe> keyframes;
  bool operator==(const EffectTrack&) const = default;
};

}  // namespace vdfx::effects
