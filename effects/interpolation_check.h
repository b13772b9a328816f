/// @file
/// @brief The one check of interpolation settings: the RBF kernel, the sidecar reader and the
/// editor's document all ask it, so the accepted ranges and their messages agree everywhere.
#pragma once

#include <optional>
#include <string>

#include "effects/keyframe.h"

namespace vdfx::effects {

/// Why `exponent` is not accepted ("exponent 5 is out of range (0, 4)"), or nullopt when it is
/// (kExponentMin < exponent < kExponentMax).
std::optional<std::string> exponent_problem(double exponent);
/// Why `time_scale` is not accepted ("time_scale 0 is out of range (0, 1000]"), or nullopt when
/// it is (kTimeScaleMin < time_scale <= kTimeScaleMax).
std::optional<std::string> time_scale_problem(double time_scale);
/// Why `reach_s` is not accepted ("reach_s 0 is out of range (0, 1e+07]"), or nullopt when it is
/// (kReachMinS < reach_s <= kReachMaxS).
std::optional<std::string> reach_problem(double reach_s);
/// The first problem of `s`: exponent, time scale, reach, then the distance and outside_span
/// values (an enum cast from a number may name none of them); nullopt when all are accepted.
std::optional<std::string> interpolation_problem(const InterpolationSettings& s);

}  // namespace vdfx::effects
