/// @file
/// @brief The refresh rate's measurement and its line in `vdfx hmd openxr`.
#include "xr/openxr/display_refresh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vdfx::xr {

std::optional<double> refresh_from_display_times(std::span<const std::int64_t> times,
                                                 std::size_t skip) {
  if (times.size() < skip + 2) return std::nullopt;
  std::vector<std::int64_t> intervals;
  for (std::size_t i = skip + 1; i < times.size(); ++i)
    intervals.push_back(times[i] - times[i - 1]);
  auto mid = intervals.begin() + static_cast<std::ptrdiff_t>(intervals.size() / 2);
  std::nth_element(intervals.begin(), mid, intervals.end());
  double median = static_cast<double>(*mid);
  if (intervals.size() % 2 == 0) {  // the mean of the two middle ones
    const auto below = std::max_element(intervals.begin(), mid);
    median = 0.5 * (median + static_cast<double>(*below));
  }
  if (!(median > 0.0)) return std::nullopt;
  return 1e9 / median;
}

std::string hz_text(double hz) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", std::round(hz * 100.0) / 100.0);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::string describe_refresh(const DisplayRefresh& r) {
  if (!(r.hz > 0.0)) return "unknown (the session did not run frames within 2 s)";
  std::string out = hz_text(r.hz) + " Hz (";
  if (r.from_extension) {
    out += "XR_FB_display_refresh_rate; the display offers ";
    for (std::size_t i = 0; i < r.offered_hz.size(); ++i)
      out += (i ? ", " : "") + hz_text(r.offered_hz[i]);
    return out + " Hz)";
  }
  return out + "measured: the median interval of the display times the runtime predicted for " +
         std::to_string(r.measured_intervals) + " frames; it offers no XR_FB_display_refresh_rate)";
}

}  // namespace vdfx::xr
