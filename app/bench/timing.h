/// @file
/// @brief Timing for `vdfx bench`: repeated wall-clock samples summarised by median and p90, and
/// a subject timed interleaved with its peer so that the load of a shared machine drifts alike
/// for both (the ratio of the medians is what stays meaningful when the machine is busy).
#pragma once

#include <functional>
#include <vector>

#include "app/bench/report.h"

namespace vdfx::app::bench {

/// How long to keep sampling one side of a measurement.
struct Budget {
  double min_time_s = 0.5;  //!< sample until this much time was spent ...
  int min_samples = 5;      //!< ... and at least this many samples were taken,
  int max_samples = 200;    //!< but never more than this many
};
Budget quick_budget();
Budget full_budget();

/// One timed thing. `run` does `units` units of work (e.g. 4096 points); times are per unit.
/// `reset`, when set, runs untimed after each sample (e.g. undoing an add).
struct Timed {
  Timed(std::function<void()> run_, double units_ = 1.0, std::function<void()> reset_ = {})
      : run(std::move(run_)), units(units_), reset(std::move(reset_)) {}
  std::function<void()> run;
  double units = 1.0;
  std::function<void()> reset;
};

/// Median (the upper middle of an even count) and the nearest-rank 90th percentile.
double median_of(std::vector<double> v);
double p90_of(std::vector<double> v);

/// Samples `t` within the budget. The first call is a warm-up (caches, shader variants) and is
/// dropped unless it alone took longer than a quarter second (then it counts as a sample).
TimeStats measure(const Timed& t, const Budget& budget);

struct PairTimes {
  TimeStats subject, peer;
};
/// Samples subject and peer alternately while both still need samples, then whichever does.
PairTimes measure_pair(const Timed& subject, const Timed& peer, const Budget& budget);

/// Seconds since an arbitrary start (steady clock).
double now_s();

/// CPU seconds this process has used (all its threads).
double process_cpu_s();

/// CPU and wall time of `t`, per unit, over `runs` runs (resets untimed): on a shared machine the
/// wall time of a sample includes waits for a core, the CPU time does not.
struct CpuWall {
  double cpu_s = 0.0, wall_s = 0.0;
};
CpuWall measure_cpu(const Timed& t, int runs);

}  // namespace vdfx::app::bench
