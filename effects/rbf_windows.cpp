/// @file
/// @brief The window layout of local interpolation in time: planning, data ranges, blending.
#include "effects/rbf_windows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace vdfx::effects {

namespace {

/// A frame position as an integer frame, clamped into int64's range (frames may be near 2^63).
std::int64_t clamp_frame(double x) {
  constexpr double lo = -9.2e18, hi = 9.2e18;
  return static_cast<std::int64_t>(std::clamp(x, lo, hi));
}

std::size_t lower(std::span<const std::int64_t> f, std::int64_t v) {
  return static_cast<std::size_t>(std::lower_bound(f.begin(), f.end(), v) - f.begin());
}
std::size_t upper(std::span<const std::int64_t> f, std::int64_t v) {
  return static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), v) - f.begin());
}

/// The layout with width `w` over the frames (count only; checked by the caller).
WindowLayout layout_of(double w, std::span<const std::int64_t> f, bool automatic) {
  WindowLayout l;
  l.width = w;
  l.automatic = automatic;
  const double j0 = std::floor(static_cast<double>(f.front()) / w);
  const double j1 = std::floor(static_cast<double>(f.back()) / w);
  l.first = clamp_frame(j0);
  l.count = static_cast<int>(std::min(j1 - j0 + 1.0, kMaxWindows + 1.0));
  return l;
}

WindowData data_of(const WindowLayout& l, int j, std::span<const std::int64_t> f) {
  const double start = l.core_start(j), end = start + l.width;
  const double d = l.blend(), m = l.margin();
  WindowData w;
  w.lo = clamp_frame(std::ceil(start - d - m));
  w.hi = clamp_frame(std::floor(end + d + m));
  w.begin = lower(f, w.lo);
  w.end = upper(f, w.hi);
  // Across a gap: at least kMinMarginKeyframes keyframes beyond the frames the window weighs,
  // whole frames, so that the window's data never depends on the order of equal frames.
  const std::size_t support_begin = lower(f, clamp_frame(std::ceil(start - d)));
  const std::size_t support_end = upper(f, clamp_frame(std::floor(end + d)));
  if (support_begin - w.begin < kMinMarginKeyframes && w.begin > 0) {
    const std::size_t k =
        support_begin > kMinMarginKeyframes ? support_begin - kMinMarginKeyframes : 0;
    if (k < w.begin) {
      w.lo = f[k];
      w.begin = lower(f, w.lo);
    }
  }
  if (w.end - support_end < kMinMarginKeyframes && w.end < f.size()) {
    const std::size_t k = std::min(f.size(), support_end + kMinMarginKeyframes);
    if (k > w.end) {
      w.hi = f[k - 1];
      w.end = upper(f, w.hi);
    }
  }
  return w;
}

std::size_t largest(const WindowLayout& l, std::span<const std::int64_t> f, int* at = nullptr) {
  std::size_t most = 0;
  for (int j = 0; j < l.count; ++j) {
    const std::size_t s = data_of(l, j, f).size();
    if (s > most) {
      most = s;
      if (at) *at = j;
    }
  }
  return most;
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::vector<WindowData> window_data(const WindowLayout& layout,
                                    std::span<const std::int64_t> sorted_frames) {
  std::vector<WindowData> out;
  out.reserve(static_cast<std::size_t>(std::max(layout.count, 0)));
  for (int j = 0; j < layout.count; ++j) out.push_back(data_of(layout, j, sorted_frames));
  return out;
}

std::optional<WindowLayout> plan_windows(const InterpolationSettings& settings, double fps,
                                         std::span<const std::int64_t> f) {
  if (f.empty()) return std::nullopt;
  if (settings.reach_s) return layout_of(std::max(1.0, *settings.reach_s * fps), f, false);
  if (f.size() <= kGlobalSolveMaxKeyframes) return std::nullopt;
  const double span = static_cast<double>(f.back()) - static_cast<double>(f.front()) + 1.0;
  const double ideal = kAutoWindowKeyframes * span / static_cast<double>(f.size());
  double w = std::max(1.0, std::exp2(std::round(std::log2(std::max(ideal, 1.0)))));
  // Fewer windows than the cap, then no window fuller than a dense solve takes (if halving can
  // get there: keyframes crowded into a few frames cannot be split in time).
  while (layout_of(w, f, true).count > kMaxWindows) w *= 2.0;
  while (w > 1.0 && largest(layout_of(w, f, true), f) > kMaxWindowKeyframes &&
         layout_of(w / 2.0, f, true).count <= kMaxWindows)
    w /= 2.0;
  return layout_of(w, f, true);
}

std::optional<std::string> window_problem(const InterpolationSettings& settings, double fps,
                                          std::span<const std::int64_t> f) {
  const auto layout = plan_windows(settings, fps, f);
  if (!layout) return std::nullopt;  // the global solve: at most kGlobalSolveMaxKeyframes
  const std::string reach = settings.reach_s
                                ? "reach_s " + short_num(*settings.reach_s)
                                : "the automatic reach of " + short_num(layout->width / fps) + " s";
  if (layout->count > kMaxWindows)
    return reach + " splits the keyframes' frames " + std::to_string(f.front()) + " to " +
           std::to_string(f.back()) + " into more than " + std::to_string(kMaxWindows) +
           " windows: raise reach_s";
  int at = 0;
  const std::size_t most = largest(*layout, f, &at);
  if (most <= kMaxWindowKeyframes) return std::nullopt;
  const WindowData d = data_of(*layout, at, f);
  const std::int64_t lo = f[d.begin], hi = f[d.end - 1];
  const std::string where =
      lo == hi ? "at frame " + std::to_string(lo)
               : "between frames " + std::to_string(lo) + " and " + std::to_string(hi);
  return std::to_string(most) + " keyframes " + where +
         " fall into one window of local interpolation (" + reach + "), more than the " +
         std::to_string(kMaxWindowKeyframes) + " one window solves" +
         (settings.reach_s ? ": lower reach_s or spread them over more frames"
                           : ": spread them over more frames");
}

std::optional<std::string> window_summary(const InterpolationSettings& settings, double fps,
                                          std::span<const std::int64_t> f) {
  const auto layout = plan_windows(settings, fps, f);
  if (!layout || layout->count > kMaxWindows) return std::nullopt;
  const std::size_t most = largest(*layout, f);
  return "interpolated locally in time: reach " + short_num(layout->width / fps) + " s (" +
         (layout->automatic ? "automatic" : "reach_s") + "), " + std::to_string(layout->count) +
         (layout->count == 1 ? " window of " : " windows of at most ") + std::to_string(most) +
         " keyframes";
}

double blend_weight(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * s * (s * (s * 6.0 - 15.0) + 10.0);
}

WindowBlend blend_at(const WindowLayout& l, double frame) {
  const double jj = std::floor(frame / l.width) - static_cast<double>(l.first);
  const int j = static_cast<int>(std::clamp(jj, 0.0, static_cast<double>(l.count - 1)));
  const double a = frame - l.core_start(j), d = l.blend();
  if (j > 0 && a < d) return {j - 1, j, blend_weight((a + d) / (2.0 * d))};
  if (j + 1 < l.count && a > l.width - d)
    return {j, j + 1, blend_weight((a - (l.width - d)) / (2.0 * d))};
  return {j, j, 0.0};
}

}  // namespace vdfx::effects
