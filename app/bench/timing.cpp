/// @file
/// @brief Sampling loops of `vdfx bench` and their summaries.
#include "app/bench/timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace vdfx::app::bench {

Budget quick_budget() {
  return {0.15, 3, 40};
}
Budget full_budget() {
  return {0.5, 5, 200};
}

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

CpuWall measure_cpu(const Timed& t, int runs) {
  CpuWall s;
  for (int i = 0; i < runs; ++i) {
    const double c0 = process_cpu_s(), w0 = now_s();
    t.run();
    s.cpu_s += process_cpu_s() - c0;
    s.wall_s += now_s() - w0;
    if (t.reset) t.reset();
  }
  const double units = t.units * std::max(runs, 1);
  s.cpu_s /= units;
  s.wall_s /= units;
  return s;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return kNaN;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double p90_of(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(v.size())));
  return v[std::max<std::size_t>(rank, 1) - 1];
}

namespace {

/// One side's samples and the time spent on them.
struct Side {
  const Timed* timed;
  std::vector<double> per_unit;
  double spent = 0.0;

  explicit Side(const Timed& t) : timed(&t) {}
  double once() {
    const double t0 = now_s();
    timed->run();
    const double dt = now_s() - t0;
    if (timed->reset) timed->reset();
    return dt;
  }
  void warm_up() {
    const double dt = once();
    if (dt > 0.25) keep(dt);  // too costly to throw away; its caches were cold, the median copes
  }
  void keep(double dt) {
    per_unit.push_back(dt / timed->units);
    spent += dt;
  }
  void sample() { keep(once()); }
  bool wants(const Budget& b) const {
    const int n = static_cast<int>(per_unit.size());
    if (n >= b.max_samples) return false;
    if (n < b.min_samples) return true;
    return spent < b.min_time_s;
  }
  TimeStats stats() const {
    return {median_of(per_unit), p90_of(per_unit), static_cast<int>(per_unit.size())};
  }
};

}  // namespace

TimeStats measure(const Timed& t, const Budget& budget) {
  Side s(t);
  s.warm_up();
  while (s.wants(budget)) s.sample();
  return s.stats();
}

PairTimes measure_pair(const Timed& subject, const Timed& peer, const Budget& budget) {
  Side a(subject), b(peer);
  a.warm_up();
  b.warm_up();
  for (;;) {
    const bool wa = a.wants(budget), wb = b.wants(budget);
    if (!wa && !wb) break;
    if (wa) a.sample();
    if (wb) b.sample();
  }
  return {a.stats(), b.stats()};
}

}  // namespace vdfx::app::bench
