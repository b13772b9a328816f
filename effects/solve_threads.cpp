/// @file
/// @brief The solve's thread count and its split of independent loops.
#include "effects/solve_threads.h"

#if !defined(__EMSCRIPTEN__)
#include <pthread.h>
#endif
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sched.h>
#define VDFX_CPU_AFFINITY 1
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
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

int usable_cpus() {
#if defined(VDFX_CPU_AFFINITY)
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return std::max(1, CPU_COUNT(&allowed));
#endif
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
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

namespace {

#if !defined(__EMSCRIPTEN__)
/// The helper threads, started when first needed and kept: a thread's start and its move off
/// its creator's CPU cost about 0.1 ms, and one solve shares out a dozen loops. A run's tasks
/// are claimed one at a time by whichever thread comes first, the caller included, and the
/// caller waits only for tasks a helper has claimed: a helper that the system does not run
/// meanwhile (the other core busy) holds nothing up. One caller at a time; another (or a task
/// that shares out a loop of its own) runs its tasks in turn instead.
class HelperPool {
 public:
  static HelperPool& get() {
    static std::once_flag once;
    std::call_once(once, [] {
      // A child forked while helpers ran has none: it starts its own.
      pthread_atfork(nullptr, nullptr, [] { pool() = new HelperPool; });
    });
    return *pool();
  }

  /// False, running nothing, where another caller holds the helpers.
  bool try_run(std::span<const std::function<void()>> tasks) {
    // A flag, not a mutex: the caller's own tasks may ask again (a mutex's owner may not).
    bool expected = false;
    if (!busy_.compare_exchange_strong(expected, true, std::memory_order_acquire)) return false;
    struct Release {
      std::atomic<bool>& busy;
      ~Release() { busy.store(false, std::memory_order_release); }
    } release{busy_};
    const int cpu = current_cpu();
    const std::size_t wanted =
        std::min(tasks.size(), static_cast<std::size_t>(solve_threads())) - 1;
    while (helpers_.size() < wanted) helpers_.push_back(std::make_unique<Helper>(cpu));
    const auto job = std::make_shared<Job>(tasks);
    for (std::size_t h = 0; h < wanted; ++h) helpers_[h]->post(job);
    job->work();
    // Only tasks already claimed are waited for (each is a fraction of a millisecond): spun.
    for (int spins = 0; job->done.load(std::memory_order_acquire) < tasks.size(); ++spins)
      if (spins > 4000) std::this_thread::yield();
    return true;
  }

 private:
  /// One run's tasks. Shared with the helpers: one that looks only after the run has ended
  /// finds nothing left to claim and never reads the tasks (the caller's, gone by then).
  struct Job {
    explicit Job(std::span<const std::function<void()>> t) : tasks(t) {}
    /// Claims and runs tasks until none is left.
    void work() {
      for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < tasks.size();) {
        tasks[k]();  // the callers' tasks catch their own exceptions (parallel_parts' do)
        done.fetch_add(1, std::memory_order_release);
      }
    }
    std::span<const std::function<void()>> tasks;
    std::atomic<std::size_t> next{0}, done{0};
  };

  /// One kept thread: waits for a run, helps with it.
  class Helper {
   public:
    explicit Helper(int creator_cpu) {
      std::thread([this, creator_cpu] {
        leave_creators_cpu(creator_cpu);
        loop();
      }).detach();  // kept for the process's life, as the pool is
    }
    void post(std::shared_ptr<Job> job) {
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        job_ = std::move(job);
        posted_.fetch_add(1, std::memory_order_release);
      }
      wake_.notify_one();
    }

   private:
    void loop() {
      for (unsigned seen = 0;;) {
        wait_for_post(seen);
        std::shared_ptr<Job> job;
        {
          const std::lock_guard<std::mutex> lock(mutex_);
          seen = posted_.load(std::memory_order_relaxed);
          job = std::move(job_);
        }
        if (job) job->work();
      }
    }
    /// Until a run is posted after the `seen`th: looked for without sleeping for kStayAwake (a
    /// solve's loops come a fraction of a millisecond apart; waking a sleeping thread took about
    /// 50 us on this project's virtual machine), then waited for.
    void wait_for_post(unsigned seen) {
      const auto until = std::chrono::steady_clock::now() + kStayAwake;
      for (unsigned spins = 1;; ++spins) {
        if (posted_.load(std::memory_order_acquire) != seen) return;
#if defined(__x86_64__)
        __builtin_ia32_pause();
#endif
        if (spins % 256 == 0 && std::chrono::steady_clock::now() > until) break;
      }
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return posted_.load(std::memory_order_relaxed) != seen; });
    }

    static constexpr std::chrono::milliseconds kStayAwake{2};
    std::mutex mutex_;
    std::condition_variable wake_;
    std::shared_ptr<Job> job_;
    std::atomic<unsigned> posted_{0};
  };

  static HelperPool*& pool() {
    static HelperPool* p = new HelperPool;  // never destroyed: its threads outlive main
    return p;
  }

  std::atomic<bool> busy_{false};  // a run is under way
  std::vector<std::unique_ptr<Helper>> helpers_;
};
#endif

}  // namespace

bool try_run_on_helpers(std::span<const std::function<void()>> tasks) {
#if defined(__EMSCRIPTEN__)  // the web module is built without threads
  return tasks.empty();
#else
  if (tasks.size() <= 1) {
    for (const auto& task : tasks) task();
    return true;
  }
  return HelperPool::get().try_run(tasks);
#endif
}

void run_on_helpers(std::span<const std::function<void()>> tasks) {
  if (!try_run_on_helpers(tasks))
    for (const auto& task : tasks) task();
}

void for_each_part(int parts, const std::function<void(int part)>& fn) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(parts));
  std::vector<std::function<void()>> tasks;
  for (int k = 0; k < parts; ++k)
    tasks.emplace_back([&fn, &errors, k] {
      try {
        fn(k);
      } catch (...) {
        errors[static_cast<std::size_t>(k)] = std::current_exception();
      }
    });
  run_on_helpers(tasks);
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
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
  for_each_part(parts, [&at, &fn](int k) {
    fn(at[static_cast<std::size_t>(k)], at[static_cast<std::size_t>(k) + 1]);
  });
}

std::ptrdiff_t triangle_cut(std::ptrdiff_t n, int k, int parts) {
  // Work left after column j is (n - j)^2 / 2: part k ends where (parts - k) / parts of it is left.
  const double left = std::sqrt(static_cast<double>(parts - k) / parts);
  return static_cast<std::ptrdiff_t>(std::lround(static_cast<double>(n) * (1.0 - left)));
}

}  // namespace vdfx::effects
