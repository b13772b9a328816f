/// @file
/// @brief Local interpolation in time: the windows a partition of unity over the frame axis
/// splits one effect's keyframes into (docs/interpolation.md, "Local interpolation").
///
/// Window j owns the frames [J W, (J + 1) W), J = first + j (its core; W, the window width, is
/// the reach in frames). Around each boundary between two windows a blend zone of half-width
/// W / 4 mixes their interpolants with weights that sum to one (a quintic smoothstep: value,
/// slope and curvature are continuous). Each window solves the keyframes whose frames lie within
/// the reach W of the frames it weighs (its core and its blend zones), and at least
/// kMinMarginKeyframes more on each side across a gap, so every keyframe is still reproduced
/// exactly: each window that weighs a keyframe's frame holds that keyframe. The layout depends
/// only on the keyframes' frames, the settings and fps, never on the order of edits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "effects/keyframe.h"

namespace vdfx::effects {

/// Without reach_s, effects with at most this many keyframes are solved globally (every sidecar
/// accepted while that was the only scheme evaluates as it did); more are interpolated locally.
inline constexpr std::size_t kGlobalSolveMaxKeyframes = 4096;
/// The most keyframes one window may solve: a window is a dense solve (O(m^2) memory, O(m^3)
/// time), the global solve's own limit.
inline constexpr std::size_t kMaxWindowKeyframes = 4096;
/// The automatic reach aims at about this many keyframes per window core (a power of two in
/// frames nearest to it, so that an edit rarely changes it): the speed-against-error knob's
/// default (docs/interpolation.md measures both).
inline constexpr double kAutoWindowKeyframes = 64.0;
/// Across a gap a window reaches at least this many keyframes on each side (whole frames).
inline constexpr std::size_t kMinMarginKeyframes = 8;
/// The most windows a layout may have: windows in a gap share one solve, but each still costs
/// its slot (a reach of one frame over 2^20 frames, about 10 hours at 30 fps).
inline constexpr int kMaxWindows = 1 << 20;

struct WindowLayout {
  double width = 1.0;      //!< W, frames (>= 1): each window's core, and its reach
  std::int64_t first = 0;  //!< J of window 0: floor(first keyframe frame / W)
  int count = 0;           //!< windows, covering the keyframes' frame span
  bool automatic = false;  //!< W chosen from the keyframes' density (no reach_s)
  double blend() const { return width / 4.0; }
  double margin() const { return width; }
  double core_start(int j) const { return static_cast<double>(first + j) * width; }
  bool operator==(const WindowLayout&) const = default;
};

/// The keyframes window j solves: those with frames in [lo, hi], positions [begin, end) of the
/// ascending frame list the layout was made from.
struct WindowData {
  std::int64_t lo = 0, hi = 0;
  std::size_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
  bool operator==(const WindowData&) const = default;
};

/// Every window's data, for `sorted_frames` (ascending).
std::vector<WindowData> window_data(const WindowLayout& layout,
                                    std::span<const std::int64_t> sorted_frames);

/// The layout for keyframes at `sorted_frames` (ascending): nullopt for the global solve (no
/// keyframes, or none of reach_s and more than kGlobalSolveMaxKeyframes keyframes). With reach_s
/// W = reach_s * fps (at least one frame); without it W is the power of two nearest to
/// kAutoWindowKeyframes keyframes' share of the span, halved while a window holds more than
/// kMaxWindowKeyframes. The window too full to solve, if any, is reported by window_problem.
std::optional<WindowLayout> plan_windows(const InterpolationSettings& settings, double fps,
                                         std::span<const std::int64_t> sorted_frames);

/// Why these keyframes cannot be interpolated (a window holds more than kMaxWindowKeyframes:
/// "5000 keyframes between frames 10 and 12 fall into one window ..."), or nullopt.
std::optional<std::string> window_problem(const InterpolationSettings& settings, double fps,
                                          std::span<const std::int64_t> sorted_frames);

/// How keyframes at `sorted_frames` are interpolated, for people (vdfx validate): nullopt for
/// the global solve, else "interpolated locally in time: reach 0.533 s (automatic), 2250
/// windows of at most 310 keyframes".
std::optional<std::string> window_summary(const InterpolationSettings& settings, double fps,
                                          std::span<const std::int64_t> sorted_frames);

/// The windows that weigh `frame` and the weight of the second: the value is
/// (1 - weight) f_a + weight f_b; b == a (weight 0) outside blend zones. Frames outside the
/// windows (extrapolation) use the nearest window alone.
struct WindowBlend {
  int a = 0, b = 0;
  double weight = 0.0;
};
WindowBlend blend_at(const WindowLayout& layout, double frame);

/// The quintic smoothstep 6 s^5 - 15 s^4 + 10 s^3 on [0, 1] (clamped): the blend weight.
double blend_weight(double s);

}  // namespace vdfx::effects
