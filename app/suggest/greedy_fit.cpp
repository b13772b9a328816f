/// @file
/// @brief Greedy keyframe insertion (greedy_fit.h).
#include "app/suggest/greedy_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <set>
#include <stdexcept>

#include "effects/keyframe_set.h"
#include "effects/rbf_interpolator.h"

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

/// The interpolant at every sample against the target, the samples shared out over every core
/// (each sample on its own: the result does not depend on how they were shared).
Errors measure(const TargetField& field, const effects::RbfInterpolator& f,
               const std::vector<Eigen::Vector3d>& units) {
  Errors e;
  const std::size_t n = field.size();
  e.error.resize(n);
  std::vector<double> squares(n);
  const int d = field.dimension;
  constexpr int kChunk = 256;  // samples a task: few tasks, each long enough to pay for itself
  const int chunks = static_cast<int>((n + kChunk - 1) / kChunk);
  cv::parallel_for_(cv::Range(0, chunks), [&](const cv::Range& range) {
    std::vector<double> value(static_cast<std::size_t>(d));
    const std::size_t end = std::min(n, static_cast<std::size_t>(range.end) * kChunk);
    for (std::size_t s = static_cast<std::size_t>(range.start) * kChunk; s < end; ++s) {
      f.evaluate_into(units[s], field.frames[s], value.data());
      double err = 0.0, sq = 0.0;
      for (int c = 0; c < d; ++c) {
        const double diff = value[c] - field.values[s * d + c];
        err = std::max(err, std::abs(diff));
        sq += diff * diff;
      }
      e.error[s] = err;
      squares[s] = sq;
    }
  });
  for (std::size_t s = 0; s < n; ++s) {
    e.max_error = std::max(e.max_error, e.error[s]);
    e.sum_squares += squares[s];
  }
  return e;
}

/// The interpolant of the keyframes placed so far. Small steps go through the editor's
/// incremental solver (effects::KeyframeSet: an O(N^2) bordered update per keyframe); once a
/// step places kFullSolveStep keyframes or more, one full solve of all of them costs less than
/// that many updates of a matrix that has outgrown the cache, and every later step solves afresh.
class Interpolant {
 public:
  static constexpr std::size_t kFullSolveStep = 64;

  Interpolant(int dimension, const FitOptions& options,
              const std::vector<effects::Keyframe>& existing)
      : dimension_(dimension), options_(options), all_(existing) {
    effects::KeyframeSetOptions set_options;
    set_options.async = false;
    set_ = std::make_unique<effects::KeyframeSet>(dimension, options.settings, options.fps,
                                                  existing, set_options, options.neutral);
    current_ = set_->solution();
  }

  void add(const std::vector<effects::Keyframe>& step) {
    all_.insert(all_.end(), step.begin(), step.end());
    if (set_ && step.size() < kFullSolveStep) {
      for (const auto& k : step) set_->add(k);
      current_ = set_->solution();
      return;
    }
    set_.reset();
    current_ = std::make_shared<const effects::RbfInterpolator>(all_, dimension_, options_.settings,
                                                                options_.fps, options_.neutral);
  }
  const effects::RbfInterpolator& current() const { return *current_; }
  const std::vector<effects::Keyframe>& keyframes() const { return all_; }

 private:
  int dimension_;
  const FitOptions& options_;
  std::vector<effects::Keyframe> all_;  //!< the author's, then the fit's
  std::unique_ptr<effects::KeyframeSet> set_;
  std::shared_ptr<const effects::RbfInterpolator> current_;
};

/// What one step places: the stamps of the worst samples, far enough apart that each fixes its
/// own part of the field.
struct Step {
  std::vector<effects::Keyframe> keyframes;
  std::size_t stamps = 0;     //!< whose keyframes these are
  bool budget_spent = false;  //!< the next stamp did not fit the budget
};

/// The placeable samples over the tolerance, worst first (ties: the lower index), sorted lazily:
/// a step mostly looks at the head of the list.
class Candidates {
 public:
  Candidates(const Errors& e, const std::vector<bool>& placeable, double tolerance,
             std::size_t head)
      : error_(e.error) {
    for (std::size_t s = 0; s < error_.size(); ++s)
      if (placeable[s] && error_[s] > tolerance) order_.push_back(s);
    sorted_ = std::min(head, order_.size());
    std::partial_sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(sorted_),
                      order_.end(), worse());
  }
  std::size_t size() const { return order_.size(); }
  std::size_t operator[](std::size_t i) {
    if (i >= sorted_) {  // past the head: the rest, once
      std::sort(order_.begin() + static_cast<std::ptrdiff_t>(sorted_), order_.end(), worse());
      sorted_ = order_.size();
    }
    return order_[i];
  }

 private:
  /// The comparison "a is worse than b".
  struct Worse {
    const std::vector<double>* error;
    bool operator()(std::size_t a, std::size_t b) const {
      return (*error)[a] != (*error)[b] ? (*error)[a] > (*error)[b] : a < b;
    }
  };
  Worse worse() const { return {&error_}; }
  const std::vector<double>& error_;
  std::vector<std::size_t> order_;
  std::size_t sorted_ = 0;
};

/// Keyframe positions in the kernel's space-time, and the nearest of them to a sample.
struct Positions {
  double time_factor = 1.0;
  std::vector<Eigen::Vector3d> units;
  std::vector<std::int64_t> frames;

  void add(const effects::Keyframe& k) {
    units.push_back(effects::to_unit(k.direction));
    frames.push_back(k.frame);
  }
  /// Squared distance from (u, f) to the nearest position (infinite without any): chordal
  /// directions and frames times the kernel's time factor, the RBF's own distance.
  double nearest_d2(const Eigen::Vector3d& u, std::int64_t f) const {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < units.size(); ++k) {
      const double dt = static_cast<double>(f - frames[k]) * time_factor;
      best = std::min(best, (u - units[k]).squaredNorm() + dt * dt);
    }
    return best;
  }
};

/// A sample joins a step only when the keyframes the step already places are further from it
/// than this many times the nearest keyframe there before: closer, one of them fixes much of its
/// error, and it waits for the next step's measure (docs/suggest.md, "Fitting").
constexpr double kStepSpacing = 1.5;

/// Everything one step's choice needs.
struct Picker {
  const TargetField& field;
  const FitOptions& options;
  const std::vector<effects::Keyframe>& existing;
  const std::vector<Eigen::Vector3d>& units;
  double time_factor = 1.0;
  std::vector<bool> placeable;   //!< a sample is picked at most once
  std::set<std::string> placed;  //!< the stamps' keys

  /// Stamps the worst placeable samples over the tolerance, worst first, up to `picks` of them,
  /// spaced by kStepSpacing. The first pick is always the worst sample: with one pick a step is
  /// the plain greedy insertion.
  Step pick(const Errors& e, const std::vector<effects::Keyframe>& there, std::size_t picks,
            std::size_t budget_left);

  /// A stamp that would replace one of the author's keyframes is not placed.
  bool clashes(const Stamp& st) const {
    return std::any_of(st.keyframes.begin(), st.keyframes.end(), [&](auto& k) {
      return std::any_of(existing.begin(), existing.end(), [&](const effects::Keyframe& x) {
        return effects::replaces(k.direction, k.frame, x);
      });
    });
  }
};

Step Picker::pick(const Errors& e, const std::vector<effects::Keyframe>& there, std::size_t picks,
                  std::size_t budget_left) {
  // Each sample looked at past the first costs a distance to every keyframe: a step looks at a
  // bounded number (the rest wait for the next step).
  std::size_t looks = 32 * picks + 64;
  Candidates order(e, placeable, options.tolerance, looks + picks);
  Positions before{time_factor, {}, {}}, placing{time_factor, {}, {}};
  if (picks > 1)
    for (const auto& k : there) before.add(k);
  Step step;
  std::size_t taken = 0;
  for (std::size_t i = 0; i < order.size() && taken < picks; ++i) {
    const std::size_t s = order[i];
    if (taken > 0) {
      if (looks-- == 0) break;
      if (placing.nearest_d2(units[s], field.frames[s]) <
          kStepSpacing * kStepSpacing * before.nearest_d2(units[s], field.frames[s]))
        continue;
    }
    placeable[s] = false;  // picked once: exact, or its stamp's keyframes are in place
    Stamp st = options.stamp ? options.stamp(s) : single_keyframe(field, s);
    if (!placed.insert(st.key).second || clashes(st)) continue;  // nothing new, or the author's
    if (step.keyframes.size() + st.keyframes.size() > budget_left) {
      step.budget_spent = true;
      break;
    }
    for (auto& k : st.keyframes) {
      placing.add(k);
      step.keyframes.push_back(std::move(k));
    }
    ++taken;
  }
  step.stamps = taken;
  return step;
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
  Picker picker{field,
                options,
                existing,
                units,
                effects::RbfKernel::from(options.settings, options.fps).time_factor,
                std::vector<bool>(n, true),
                {}};
  Interpolant f(field.dimension, options, existing);
  Errors e = measure(field, f.current(), units);
  if (options.on_step) options.on_step(0, e.max_error);
  std::size_t stamps = 0;  // placed
  while (e.max_error > options.tolerance) {
    // A step stamps more samples as they grow in number (a fixed share of the stamps and the
    // author's keyframes there), so the error passes, each over every sample, stay few.
    const auto there = static_cast<double>(existing.size() + stamps);
    const auto picks = static_cast<std::size_t>(std::max(1.0, options.step_share * there));
    const Step step =
        picker.pick(e, f.keyframes(), picks, options.max_keyframes - result.added.size());
    if (step.keyframes.empty()) break;
    stamps += step.stamps;
    ++result.steps;
    f.add(step.keyframes);
    result.added.insert(result.added.end(), step.keyframes.begin(), step.keyframes.end());
    e = measure(field, f.current(), units);
    if (options.on_step) options.on_step(result.added.size(), e.max_error);
    if (step.budget_spent) break;
  }
  result.max_error = e.max_error;
  result.rms_error = std::sqrt(e.sum_squares / static_cast<double>(n * field.dimension));
  result.within_tolerance = e.max_error <= options.tolerance;
  return result;
}

}  // namespace vdfx::app::suggest
