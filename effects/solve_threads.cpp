/// @file
/// @brief The solve's thread count and its split of independent loops.
#include "effects/solve_threads.h"

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sched.h>
#define VDFX_CPU_AFFINITY 1
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>
#include <vector>

namespace vdfx::effects {

namespace {
std::atomic<int> g_threads{1};
}

void set_solve_threads(int threads) {
  g_threads.store(std::clamp(threads, 1, 8), std::memory_order_relaxed);
}

int solve_threads() {
  return g_threads.load(std::memory_order_relaxed);
}

int current_cpu() {
#if defined(VDFX_CPU_AFFINITY)
  return sched_getcpu();
#else
  return -1;
#endif
}

void leave_creators_cpu(int creator_cpu) {
#if defined(VDFX_CPU_AFFINITY)
  cpu_set_t allowed;
  if (creator_cpu < 0 || creator_cpu >= CPU_SETSIZE ||
      sched_getaffinity(0, sizeof allowed, &allowed) != 0)
    return;
  cpu_set_t others = allowed;
  CPU_CLR(creator_cpu, &others);
  if (CPU_COUNT(&others) == 0 || sched_getcpu() != creator_cpu) return;
  // The first call moves this thread before it returns; the second lets the scheduler move it
  // later as it sees fit (it has no reason to, while both threads run).
  if (sched_setaffinity(0, sizeof others, &others) == 0)
    sched_setaffinity(0, sizeof allowed, &allowed);
#else
  (void)creator_cpu;
#endif
}

void parallel_parts(std::ptrdiff_t n, std::ptrdiff_t min_n,
                    const std::function<std::ptrdiff_t(int k, int parts)>& cut,
                    const std::function<void(std::ptrdiff_t begin, std::ptrdiff_t end)>& fn) {
#if defined(__EMSCRIPTEN__)
  const int parts = 1;  // the web module is built without threads
#else
  const int parts = n < min_n ? 1 : solve_threads();
#endif
  if (parts <= 1) {
    fn(0, n);
    return;
  }
  std::vector<std::ptrdiff_t> at{0};
  for (int k = 1; k < parts; ++k) at.push_back(std::clamp(cut(k, parts), at.back(), n));
  at.push_back(n);
  std::vector<std::thread> helpers;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(parts));
  const int cpu = current_cpu();
  for (int k = 1; k < parts; ++k)
    helpers.emplace_back([&, k] {
      leave_creators_cpu(cpu);
      try {
        fn(at[static_cast<std::size_t>(k)], at[static_cast<std::size_t>(k) + 1]);
      } catch (...) {
        errors[static_cast<std::size_t>(k)] = std::current_exception();
      }
    });
  try {
    fn(at[0], at[1]);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& t : helpers) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

std::ptrdiff_t triangle_cut(std::ptrdiff_t n, int k, int parts) {
  // Work left after column j is (n - j)^2 / 2: part k ends where (parts - k) / parts of it is left.
  const double left = std::sqrt(static_cast<double>(parts - k) / parts);
  return static_cast<std::ptrdiff_t>(std::lround(static_cast<double>(n) * (1.0 - left)));
}

}  // namespace vdfx::effects
