/// @file
/// @brief The headset display's refresh rate as `vdfx hmd openxr` reports it (docs/openxr.md).
///
/// XrFrameState::predictedDisplayPeriod is not it: before a runtime has the display's timing it
/// answers a placeholder (Monado 24.0 with its simulated headset: 16 ms, "62.5 Hz", for its first
/// frames). So the rate is, best first:
///   - the display's current rate from XR_FB_display_refresh_rate, with every rate it offers;
///   - else measured: the median interval between the display times the runtime predicts for
///     consecutive frames, once its first frames are past (kRefreshWarmupFrames), over
///     kRefreshMeasuredFrames intervals. The median, so a frame the runtime skips (an interval of
///     two periods) does not move it.
/// Pure: xr/openxr/gl/openxr_report.cpp runs the session and makes the calls.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vdfx::xr {

/// Frames not measured at the start, and intervals measured after them.
inline constexpr int kRefreshWarmupFrames = 10;
inline constexpr int kRefreshMeasuredFrames = 30;

struct DisplayRefresh {
  double hz = 0.0;                 //!< 0: unknown
  std::vector<double> offered_hz;  //!< XR_FB_display_refresh_rate's rates (empty without it)
  bool from_extension = false;     //!< hz is the extension's current rate
  int measured_intervals = 0;      //!< measured: the intervals the median was taken over
};

/// The rate from predicted display times (XrTime, ns) of consecutive frames, the first `skip`
/// frames left out: 1e9 / the median interval. Nothing with fewer than two times left or an
/// interval that is not positive (a runtime whose clock does not advance).
std::optional<double> refresh_from_display_times(std::span<const std::int64_t> times,
                                                 std::size_t skip);

/// What the report prints after "refresh": "90 Hz (XR_FB_display_refresh_rate; the display
/// offers 72, 90, 120 Hz)", "90 Hz (measured: ...)" or "unknown (...)".
std::string describe_refresh(const DisplayRefresh& refresh);

/// A rate as the report writes it: at most two decimals, no trailing zeros ("90", "59.94").
std::string hz_text(double hz);

}  // namespace vdfx::xr
