/// @file
/// @brief Greedy keyframe insertion (greedy_fit.h).
#include "app/suggest/greedy_fit.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "effects/keyframe_set.h"

namespace vdfx::app::suggest {

void TargetField::add(const effects::Direction& direction, std::int64_t frame,
                      std::span<const double> v) {
  if (static_cast<int>(v.size()) != dimension)
    throw std::invalid_argument("TargetField::add: wrong number of values");
  directions.push_back(direction);
  frames.push_back(frame);
  values.insert(values.end(), v.begin(), v.end());
}

std::vector<effects::Direction> sphere_directions(int count) {
  std::vector<effects::Direction> out;
  out.reserve(static_cast<std::size_t>(std::max(count, 0)));
  const double golden = effects::kPi * (3.0 - std::sqrt(5.0));  // the golden angle
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - (k + 0.5) * 2.0 / count;  // sin(altitude), equal-area bands
    const double az = std::remainder(k * golden, 2.0 * effects::kPi);
    out.push_back(
        {effects::wrap_azimuth_deg(az * effects::kRadToDeg), std::asin(z) * effects::kRadToDeg});
  }
  return out;
}

namespace {

/// Each sample's error (largest over components) and the totals.
struct Errors {
  std::vector<double> error;
  double max_error = 0.0;
  double sum_squares = 0.0;
};

Errors measure(const TargetField& field, const effects::RbfInterpolator& f,
               const std::vector<Eigen::Vector3d>& units) {
  Errors e;
  e.error.resize(field.size());
  const int d = field.dimension;
  std::vector<double> value(static_cast<std::size_t>(d));
  for (std::size_t s = 0; s < field.size(); ++s) {
    f.evaluate_into(units[s], field.frames[s], value.data());
    double err = 0.0;
    for (int c = 0; c < d; ++c) {
      const double diff = value[c] - field.values[s * d + c];
      err = std::max(err, std::abs(diff));
      e.sum_squares += diff * diff;
    }
    e.error[s] = err;
    e.max_error = std::max(e.max_error, err);
  }
  return e;
}

/// The placeable sample with the largest error (none: every error within `tolerance`).
std::optional<std::size_t> worst(const Errors& e, const std::vector<bool>& placeable,
                                 double tolerance) {
  std::optional<std::size_t> w;
  for (std::size_t s = 0; s < e.error.size(); ++s)
    if (placeable[s] && e.error[s] > tolerance && (!w || e.error[s] > e.error[*w])) w = s;
  return w;
}

}  // namespace

Stamp single_keyframe(const TargetField& field, std::size_t s) {
  const auto first = field.values.begin() + static_cast<std::ptrdiff_t>(s * field.dimension);
  Stamp st;
  st.keyframes.push_back(
      {field.directions[s], field.frames[s], std::vector<double>(first, first + field.dimension)});
  st.key = std::to_string(s);
  return st;
}

FitResult fit_greedy(const TargetField& field, const FitOptions& options,
                     const std::vector<effects::Keyframe>& existing) {
  FitResult result;
  const std::size_t n = field.size();
  if (n == 0) return result;
  std::vector<Eigen::Vector3d> units;
  units.reserve(n);
  for (const auto& d : field.directions) units.push_back(effects::to_unit(d));
  // A sample is picked at most once; one whose stamp would replace an author's keyframe is
  // skipped when picked (below).
  std::vector<bool> placeable(n, true);

  effects::KeyframeSetOptions set_options;
  set_options.async = false;
  effects::KeyframeSet set(field.dimension, options.settings, options.fps, existing, set_options,
                           options.neutral);
  std::set<std::string> placed;
  Errors e = measure(field, *set.solution(), units);
  if (options.on_step) options.on_step(0, e.max_error);
  while (e.max_error > options.tolerance) {
    const auto s = worst(e, placeable, options.tolerance);
    if (!s) break;
    placeable[*s] = false;  // picked once: exact, or its stamp's keyframes are in place
    Stamp st = options.stamp ? options.stamp(*s) : single_keyframe(field, *s);
    if (!placed.insert(st.key).second) continue;
    // A stamp that would replace one of the author's keyframes is not placed.
    const bool clashes = std::any_of(st.keyframes.begin(), st.keyframes.end(), [&](auto& k) {
      return std::any_of(existing.begin(), existing.end(), [&](const effects::Keyframe& x) {
        return effects::replaces(k.direction, k.frame, x);
      });
    });
    if (clashes) continue;
    if (result.added.size() + st.keyframes.size() > options.max_keyframes) break;
    for (auto& k : st.keyframes) {
      set.add(k);
      result.added.push_back(std::move(k));
    }
    e = measure(field, *set.solution(), units);
    if (options.on_step) options.on_step(result.added.size(), e.max_error);
  }
  result.max_error = e.max_error;
  result.rms_error = std::sqrt(e.sum_squares / static_cast<double>(n * field.dimension));
  result.within_tolerance = e.max_error <= options.tolerance;
  return result;
}

}  // namespace vdfx::app::suggest
