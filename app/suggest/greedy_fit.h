/// @file
/// @brief The fewest keyframes that reproduce a target field (docs/suggest.md, "Fitting"): greedy
/// insertion. Each step evaluates the interpolant at every sample and places keyframes, with the
/// target's values, at the samples where it is furthest from the target (one a step while the
/// keyframes are few, then a share of them, spaced apart); it stops when every sample is within
/// the tolerance or the keyframe budget is spent.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "effects/coords.h"
#include "effects/keyframe.h"

namespace vdfx::app::suggest {

/// A field of target parameter values over (direction, frame) samples.
struct TargetField {
  int dimension = 1;
  std::vector<effects::Direction> directions;  //!< one per sample
  std::vector<std::int64_t> frames;            //!< one per sample
  std::vector<double> values;                  //!< dimension values per sample, sample-major

  std::size_t size() const { return directions.size(); }
  void add(const effects::Direction& direction, std::int64_t frame, std::span<const double> v);
};

/// What one step of the fit places for the sample it picked: by default the one keyframe at the
/// sample. Fields with structure use a larger stamp (a field that does not vary with direction:
/// the same value at a few directions spread over the sphere; one constant over a frame range: the
/// same keyframe at the range's first and last frame, so the hold rule and the interpolation
/// between two equal slices keep it constant). Steps whose stamp has a key already placed are
/// skipped (they would only replace keyframes with themselves).
struct Stamp {
  std::vector<effects::Keyframe> keyframes;
  std::string key;
};
using StampFn = std::function<Stamp(std::size_t sample)>;

struct FitOptions {
  double tolerance = 0.1;          //!< largest error allowed at any sample, in parameter units
  std::size_t max_keyframes = 64;  //!< keyframes the fit may add
  effects::InterpolationSettings settings;
  double fps = 30.0;
  std::vector<double> neutral;  //!< the effect's neutral values (what no keyframes evaluate to)
  StampFn stamp;                //!< none: one keyframe at the picked sample
  /// Samples a step stamps, as a share of those already stamped and the author's keyframes:
  /// max(1, share x N) (0: one a step, the plain greedy insertion). docs/suggest.md, "Fitting",
  /// says what it trades.
  double step_share = 0.125;
  /// Called once the starting error is known and after each step, with the keyframes added so
  /// far and the largest error over the samples now (progress; it may throw to stop the fit,
  /// which then leaves nothing behind).
  std::function<void(std::size_t added, double max_error)> on_step;
};

struct FitResult {
  std::vector<effects::Keyframe> added;  //!< in the order they were placed
  double max_error = 0.0;                //!< over every sample and component, after the fit
  double rms_error = 0.0;
  bool within_tolerance = false;  //!< false: the budget ran out first
  std::size_t steps = 0;  //!< steps that placed keyframes (each one measure of every sample)
};

/// Fits `field` by adding keyframes (`options.stamp`'s, at most max_keyframes in all) to `existing`
/// (kept as they are: a merge). Samples within effects::kReplaceAngleDeg of an existing keyframe at
/// the same frame are never placed on (the author's keyframe would be replaced), though their error
/// counts.
FitResult fit_greedy(const TargetField& field, const FitOptions& options,
                     const std::vector<effects::Keyframe>& existing = {});

/// The default stamp: the keyframe at sample `s` with its target.
Stamp single_keyframe(const TargetField& field, std::size_t s);

/// `count` directions spread evenly over the sphere (a Fibonacci lattice), the samples' grid.
std::vector<effects::Direction> sphere_directions(int count);

}  // namespace vdfx::app::suggest
