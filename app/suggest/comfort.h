/// @file
/// @brief The comfort vignette (docs/suggest.md, "Comfort vignette"): the view narrows while the
/// camera turns fast, after the dynamic field-of-view restriction of Fernandes and Feiner
/// ("Combating VR Sickness through Subtle Dynamic Field-Of-View Modification", IEEE 3DUI 2016),
/// which narrows a seated viewer's field of view with the visually perceived motion and restores
/// it when the motion stops. Here the motion is the camera's own rotation, measured from the video
/// (motion.h). vdfx's mapping (its constants are vdfx's choices, not the paper's):
///   w = clamp((speed - kComfortStartDegPerS) / (kComfortFullDegPerS - kComfortStartDegPerS), 0, 1)
///   radius = kComfortOpenRadiusDeg - strength x w x (kComfortOpenRadiusDeg - kComfortMinRadiusDeg)
///   falloff = kComfortFalloffDeg
/// with speed the camera's angular speed in degrees per second, taken as the largest over the
/// frames within kComfortLeadSeconds either side (the vignette is already closing when a fast
/// turn starts and opens only after it ends: an offline suggestion can look ahead).
#pragma once

#include <cstdint>
#include <vector>

namespace vdfx::app::suggest {

inline constexpr double kComfortStartDegPerS = 15.0;   //!< below: the view stays open
inline constexpr double kComfortFullDegPerS = 90.0;    //!< from here: the narrowest view
inline constexpr double kComfortOpenRadiusDeg = 90.0;  //!< outside any headset's field of view
inline constexpr double kComfortMinRadiusDeg = 30.0;   //!< the narrowest (a 60 degree clear centre)
inline constexpr double kComfortFalloffDeg = 20.0;
inline constexpr double kComfortLeadSeconds = 0.5;
inline constexpr double kVignetteToleranceDeg = 3.0;

/// The vignette radius for an angular speed (degrees per second) and a strength in [0, 1].
double comfort_radius_deg(double speed_deg_per_s, double strength);

/// Each frame's speed replaced by the largest within `lead` frames either side.
std::vector<double> look_ahead_max(const std::vector<double>& speed, std::int64_t lead);

}  // namespace vdfx::app::suggest
