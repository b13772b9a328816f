/// @file
/// @brief GL timestamp queries around named stages (for --stats and the benchmarks).
///
/// Timestamps (glQueryCounter GL_TIMESTAMP) rather than GL_TIME_ELAPSED so stages may nest.
/// collect() waits for the results: call it after the frame, never inside one.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vdfx::xr {

struct StageTime {
  std::string stage;
  double ms = 0.0;
};

class GpuTimer {
 public:
  GpuTimer() = default;
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void start(const std::string& stage);
  void stop();  //!< ends the most recently started stage still open
  /// Stage durations of everything started since the last collect, in start order.
  std::vector<StageTime> collect();

 private:
  struct Pending {
    std::string stage;
    unsigned begin = 0, end = 0;
  };
  std::vector<Pending> pending_;
  std::vector<size_t> open_;
};

/// Wall time of `work` with the GL pipeline drained before and after (glFinish), in ms: what a
/// frame's GL work costs end to end, for tests that print figures and for the benchmarks.
double finished_wall_ms(const std::function<void()>& work);

}  // namespace vdfx::xr
