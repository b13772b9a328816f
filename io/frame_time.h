/// @file
/// @brief Playback time to frame index, exactly: rational frame rates (30000/1001) in integer
/// arithmetic, so there is no drift after hours of playback.
#pragma once

#include <cstdint>

namespace vdfx::io {

/// A frame rate num/den frames per second (num, den > 0).
struct Rational {
  std::int64_t num = 30;
  std::int64_t den = 1;
  double value() const { return static_cast<double>(num) / static_cast<double>(den); }
  bool operator==(const Rational&) const = default;
};

/// The simplest fraction (continued-fraction convergent, denominator <= 1000000) within 1e-9
/// relative of `fps`: 29.97002997... -> 30000/1001, 23.976023976... -> 24000/1001, 25 -> 25/1.
/// OpenCV reports a container's rational rate as a double; this recovers it.
Rational fps_to_rational(double fps);

/// The frame shown at playback time t_ns (nanoseconds from frame 0's start):
/// floor((t_ns + 1/2) * num / (den * 1e9)), in exact integer arithmetic. The half nanosecond is
/// the epsilon: a timestamp rounded to the nearest ns from a frame's exact start (frame_start_ns)
/// maps to that frame, not the one before. Negative times give negative frames (floor).
std::int64_t frame_at_time(std::int64_t t_ns, Rational fps);

/// Start of frame k in ns, rounded to nearest: round(k * den * 1e9 / num).
std::int64_t frame_start_ns(std::int64_t frame, Rational fps);

/// frame_at_time folded into [0, frames): wrapped when looping, clamped otherwise.
std::int64_t playback_frame(std::int64_t t_ns, Rational fps, std::int64_t frames, bool loop);

}  // namespace vdfx::io
