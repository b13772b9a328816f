/// @file
/// @brief The solve's thread count and its split of independent loops.
#include "effects/solve_threads.h"

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
  for (int k = 1; k < parts; ++k)
    helpers.emplace_back([&, k] {
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
