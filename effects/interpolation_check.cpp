/// @file
/// @brief The interpolation settings' ranges, checked in one place.
#include "effects/interpolation_check.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace vdfx::effects {

namespace {

// Shortest round-trip form ("5", "0.1"), as the sidecar reader writes numbers in its messages.
std::string num(double v) {
  char buf[32];
#if defined(__EMSCRIPTEN__)
  // The WebAssembly build's libc++ (Debian's emscripten 3.1.6) has no floating-point to_chars:
  // the fewest %g digits that read back as v, the same digits (the closest shortest form).
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
#else
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
#endif
}

std::string out_of_range(const char* name, double v, const std::string& range) {
  return std::string(name) + " " + num(v) + " is out of range " + range;
}

}  // namespace

std::optional<std::string> exponent_problem(double exponent) {
  // Written so that NaN fails too.
  if (exponent > kExponentMin && exponent < kExponentMax) return std::nullopt;
  return out_of_range("exponent", exponent,
                      "(" + num(kExponentMin) + ", " + num(kExponentMax) + ")");
}

std::optional<std::string> time_scale_problem(double time_scale) {
  if (time_scale > kTimeScaleMin && time_scale <= kTimeScaleMax) return std::nullopt;
  return out_of_range("time_scale", time_scale,
                      "(" + num(kTimeScaleMin) + ", " + num(kTimeScaleMax) + "]");
}

std::optional<std::string> reach_problem(double reach_s) {
  if (reach_s > kReachMinS && reach_s <= kReachMaxS) return std::nullopt;
  return out_of_range("reach_s", reach_s, "(" + num(kReachMinS) + ", " + num(kReachMaxS) + "]");
}

std::optional<std::string> interpolation_problem(const InterpolationSettings& s) {
  if (auto p = exponent_problem(s.exponent)) return p;
  if (auto p = time_scale_problem(s.time_scale)) return p;
  if (s.reach_s)
    if (auto p = reach_problem(*s.reach_s)) return p;
  if (s.distance != AngularDistance::Chordal && s.distance != AngularDistance::Geodesic)
    return "distance " + std::to_string(static_cast<int>(s.distance)) +
           " is neither chordal nor geodesic";
  if (s.outside != TimeOutside::Hold && s.outside != TimeOutside::Extrapolate)
    return "outside_span " + std::to_string(static_cast<int>(s.outside)) +
           " is neither hold nor extrapolate";
  return std::nullopt;
}

}  // namespace vdfx::effects
