/// @file
/// @brief A spatial keyframe and the interpolation settings of the contract.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "effects/anchor.h"
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

/// How the angular part dsigma of the RBF distance is measured between two unit directions.
/// Geodesic is the paper's angle; Chordal is |n_a - n_b| = 2 sin(angle / 2), which makes the
/// whole distance Euclidean in (x, y, z, t) and so keeps the RBF system well-posed
/// (docs/interpolation.md says why and what it changes).
enum class AngularDistance { Chordal, Geodesic };

/// What an effect does at frames outside the span of its keyframes' frames (contract, "Time,
/// as an author expects it"). Hold: the values at the nearest end of the span, so keyframes that
/// all share one frame make the effect constant over the clip. Extrapolate: the paper's
/// space-time RBF evaluated as it is (sidecar extension "outside_span": "extrapolate").
enum class TimeOutside { Hold, Extrapolate };

/// Contract: phi(d) = d^exponent; dt = |f_v - f_k| * (24 / fps) * time_scale.
struct InterpolationSettings {
  double exponent = 1.0;
  double time_scale = 1.0;
  AngularDistance distance = AngularDistance::Chordal;  //!< sidecar extension "distance"
  TimeOutside outside = TimeOutside::Hold;              //!< sidecar extension "outside_span"
  /// Local interpolation in time (sidecar extension "reach_s", effects/rbf_windows.h): how far
  /// in time, in seconds, a keyframe acts. Absent: automatic, the global solve up to
  /// kGlobalSolveMaxKeyframes keyframes and a reach chosen from the keyframes' density above.
  std::optional<double> reach_s = std::nullopt;
  bool operator==(const InterpolationSettings&) const = default;
};

/// Accepted ranges (sidecar validation and the RBF agree on these). Exponent 2 is accepted and
/// handled explicitly by the solver (r^2 is a polynomial kernel; see docs/interpolation.md).
inline constexpr double kExponentMin = 0.0;   //!< exclusive
inline constexpr double kExponentMax = 4.0;   //!< exclusive
inline constexpr double kTimeScaleMin = 0.0;  //!< exclusive: time must separate frames
inline constexpr double kTimeScaleMax = 1000.0;
inline constexpr double kReachMinS = 0.0;  //!< exclusive
inline constexpr double kReachMaxS = 1e7;  //!< about 116 days: any film

/// Time scale as an author reads it: dt for one second of video is 24 c whatever the frame
/// rate, which weighs like an angle of 24 c radians (chord ~ angle for small angles). So
/// "1 s of video weighs like D degrees of view" is c = D / (24 * 180 / pi).
inline constexpr double kDegreesPerRadian = 57.295779513082320876798;
constexpr double time_scale_from_deg_per_s(double deg_per_s) {
  return deg_per_s / (24.0 * kDegreesPerRadian);
}
constexpr double deg_per_s_from_time_scale(double c) {
  return c * 24.0 * kDegreesPerRadian;
}

/// The time scale vdfx writes into new documents: one second of video weighs like
/// kAuthorDegPerSecond degrees of view (docs/interpolation.md, "Time" explains the choice
/// against the paper's c = 1, under which one second weighs like 1375 degrees).
inline constexpr double kAuthorDegPerSecond = 2.0;
inline constexpr double kAuthorTimeScale = time_scale_from_deg_per_s(kAuthorDegPerSecond);

/// One effect's keyframe set as stored in a sidecar.
struct EffectTrack {
  EffectType type = EffectType::Exposure;
  std::optional<InterpolationSettings> interpolation;  //!< overrides the file's default
  std::vector<Keyframe> keyframes;
  Anchor anchor = {};  //!< the frame the keyframe directions are in (effects/anchor.h)
  bool operator==(const EffectTrack&) const = default;
};

}  // namespace vdfx::effects
