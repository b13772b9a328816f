/// @file
/// @brief Timing GL work in the benchmarks: wall time with the pipeline drained around it
/// (llvmpipe runs it on the CPU threads), reported as manual time, and medians of such times.
#pragma once

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "app/bench/timing.h"
#include "xr/render/gpu_timer.h"

namespace vdfx::bench {

/// Median of `times` (the upper one of an even count): the one `vdfx bench` uses.
using app::bench::median_of;
inline double median(std::vector<double> times) {
  return median_of(std::move(times));
}

/// Median wall time of `work` over `runs` runs, ms.
inline double median_wall_ms(int runs, const std::function<void()>& work) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) t.push_back(xr::finished_wall_ms(work));
  return median(std::move(t));
}

/// Runs `body` once to warm up (shader variants, meshes), then once per iteration as manual
/// time; returns the mean ms per iteration.
inline double timed_gl_loop(benchmark::State& state, const std::function<void()>& body) {
  body();
  glFinish();
  double total = 0.0;
  for (auto _ : state) {
    const double ms = xr::finished_wall_ms(body);
    state.SetIterationTime(ms * 1e-3);
    total += ms;
  }
  return total / static_cast<double>(state.iterations());
}

}  // namespace vdfx::bench
