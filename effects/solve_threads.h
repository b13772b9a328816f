/// @file
/// @brief How many threads the dense RBF solve may use for its independent loops (the kernel
/// matrix, the projected block, the exact residual): 1 unless a command asks for more. Batch
/// commands whose process does nothing else meanwhile (`vdfx eval`) use both cores; the editor,
/// the player and the benchmarks stay on one (beside them the other core renders, or times a
/// peer). The split never changes a result: every entry and every row's sum is computed in the
/// same order whatever the thread count.
#pragma once

#include <cstddef>
#include <functional>
#include <future>
#include <span>
#include <type_traits>

namespace vdfx::effects {

/// Loops shorter than this stay on one thread (a thread's start costs more than their work).
inline constexpr std::ptrdiff_t kParallelSolveMin = 384;

/// Sets the thread count (clamped to [1, 8]); process-wide, read at the start of each solve.
void set_solve_threads(int threads);
int solve_threads();

/// Runs the tasks on the calling thread and solve_threads() - 1 helper threads kept for the
/// process (started when first needed, each moved off its creator's CPU), each task taken by
/// whichever thread comes first, the caller waiting only for tasks a helper has taken; returns
/// when all have ended: true. False, running none of them, where another caller holds the
/// helpers (or a task asks for them itself), and in the web module. Tasks must not throw.
bool try_run_on_helpers(std::span<const std::function<void()>> tasks);

/// The same, running the tasks on the calling thread in turn where the helpers are not to be had.
void run_on_helpers(std::span<const std::function<void()>> tasks);

/// fn(part) for part = 0 .. parts - 1 through run_on_helpers; an exception thrown by a part
/// reaches the caller once every part has ended (the first part's, where several throw).
void for_each_part(int parts, const std::function<void(int part)>& fn);

/// Runs fn(begin, end) over [0, n) in solve_threads() parts (for_each_part);
/// parts end at `cut(k, parts)` (k = 1 .. parts - 1, ascending), so the caller can balance
/// uneven work. One part (n below `min_n`, or one thread) runs inline.
void parallel_parts(std::ptrdiff_t n, std::ptrdiff_t min_n,
                    const std::function<std::ptrdiff_t(int k, int parts)>& cut,
                    const std::function<void(std::ptrdiff_t begin, std::ptrdiff_t end)>& fn);

/// The CPUs this process may run on (its affinity mask: a container or `taskset` may allow
/// fewer than the machine has), at least 1.
int usable_cpus();

/// The CPU the calling thread runs on (-1 where that is not known).
int current_cpu();

/// Called first by a thread just started by one running on `creator_cpu`: moves it to another
/// of the process's CPUs where there is one, then allows it all of them again. Linux often
/// starts a new thread on its creator's CPU and leaves it there for milliseconds (seen on this
/// project's 2-core machine in about half of the starts), so two threads meant to share out the
/// solve took turns on one core. Does nothing with -1, one allowed CPU, or off Linux.
void leave_creators_cpu(int creator_cpu);

/// The cut for columns j = 0 .. n - 1 whose work is proportional to n - j (a lower triangle):
/// equal shares of the triangle.
std::ptrdiff_t triangle_cut(std::ptrdiff_t n, int k, int parts);

/// Starts fn() on a new thread moved off the caller's CPU (leave_creators_cpu), as std::async.
template <typename Fn>
auto async_beside(Fn fn) -> std::future<std::invoke_result_t<Fn&>> {
  return std::async(std::launch::async, [fn = std::move(fn), cpu = current_cpu()]() mutable {
    leave_creators_cpu(cpu);
    return fn();
  });
}

}  // namespace vdfx::effects
