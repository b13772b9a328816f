/// @file
/// @brief The solve's thread split (effects/solve_threads.h): any thread count gives the same
/// numbers, bit for bit, and the split covers every column and row exactly once.
#include "effects/solve_threads.h"

#include <gtest/gtest.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "effects/rbf_interpolator.h"
#include "effects/rbf_solve.h"
#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

/// Restores one thread when a test ends, whatever it set.
struct ThreadsScope {
  explicit ThreadsScope(int n) { set_solve_threads(n); }
  ~ThreadsScope() { set_solve_threads(1); }
};

/// Spins until `flag` is set, 5 s at most (a task waiting for another to start beside it).
void spin_until(const std::atomic<bool>& flag) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!flag && std::chrono::steady_clock::now() < until) {
  }
}

/// Whether `check` returns true in a forked child (this process keeps its threads and CPUs).
bool true_in_child(const std::function<bool()>& check) {
  const pid_t child = fork();
  if (child == 0) _exit(check() ? 0 : 1);
  int status = 0;
  return child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) &&
         WEXITSTATUS(status) == 0;
}

TEST(SolveThreads, PartsCoverTheRangeOnceAndBalanceATriangle) {
  const ThreadsScope scope(3);
  std::vector<std::atomic<int>> seen(1000);
  parallel_parts(
      1000, 10, [](int k, int parts) { return triangle_cut(1000, k, parts); },
      [&](std::ptrdiff_t b, std::ptrdiff_t e) {
        for (std::ptrdiff_t i = b; i < e; ++i) seen[static_cast<std::size_t>(i)]++;
      });
  for (const auto& s : seen) ASSERT_EQ(s.load(), 1);
  // Each part holds a third of the triangle's work (sum of n - j over its columns).
  const auto work = [](std::ptrdiff_t b, std::ptrdiff_t e) {
    double w = 0.0;
    for (std::ptrdiff_t j = b; j < e; ++j) w += static_cast<double>(1000 - j);
    return w;
  };
  const std::ptrdiff_t c1 = triangle_cut(1000, 1, 3), c2 = triangle_cut(1000, 2, 3);
  EXPECT_NEAR(work(0, c1) / work(0, 1000), 1.0 / 3.0, 0.01);
  EXPECT_NEAR(work(c1, c2) / work(0, 1000), 1.0 / 3.0, 0.01);
  // A part's exception reaches the caller after every part has ended.
  EXPECT_THROW(parallel_parts(
                   100, 10, [](int k, int parts) { return 100 * k / parts; },
                   [](std::ptrdiff_t b, std::ptrdiff_t) {
                     if (b > 0) throw std::runtime_error("part");
                   }),
               std::runtime_error);
}

TEST(SolveThreads, AHelperLeavesItsCreatorsCpuAndMayUseEveryCpuAfterwards) {
  cpu_set_t allowed;
  ASSERT_EQ(sched_getaffinity(0, sizeof allowed, &allowed), 0);
  if (CPU_COUNT(&allowed) < 2)
    GTEST_SKIP() << "this process may use one CPU only: no other CPU to leave for";
  // Whether the scheduler starts a thread beside its creator depends on the machine's state, so
  // the move itself is asked: a thread on CPU c that calls leave_creators_cpu(c) is elsewhere
  // when it returns, and may again run anywhere. A busy machine (the suite runs two tests at
  // once) may move it back before it looks: most calls, not all, are asked.
  int elsewhere = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::thread helper([&] {
      const int here = current_cpu();
      ASSERT_GE(here, 0);
      leave_creators_cpu(here);
      if (sched_getcpu() != here) ++elsewhere;
      cpu_set_t after;
      ASSERT_EQ(sched_getaffinity(0, sizeof after, &after), 0);
      EXPECT_TRUE(CPU_EQUAL(&after, &allowed)) << trial;
    });
    helper.join();
  }
  EXPECT_GE(elsewhere, 17);
  EXPECT_EQ(usable_cpus(), CPU_COUNT(&allowed));
  // Nothing to do: an unknown CPU, or a thread already elsewhere.
  const int here = current_cpu();
  leave_creators_cpu(-1);
  EXPECT_EQ(current_cpu(), here);
  leave_creators_cpu(here == 0 ? 1 : 0);
  EXPECT_EQ(current_cpu(), here);
  cpu_set_t now;
  sched_getaffinity(0, sizeof now, &now);
  EXPECT_TRUE(CPU_EQUAL(&now, &allowed));
}

TEST(SolveThreads, HelpersRunEachTaskOnceBesideTheCallerAndAreNotNested) {
  const ThreadsScope scope(2);
  for (int round = 0; round < 3; ++round) {  // the same kept helper, again
    std::array<std::atomic<int>, 6> runs{};
    std::array<std::thread::id, 2> first_two;
    std::atomic<bool> second_started{false};
    std::atomic<int> inner_ran{0};
    std::atomic<bool> nested_refused{false};
    std::vector<std::function<void()>> tasks;
    // Tasks 0 and 1 are taken first, one by each thread: task 0 waits (5 s at most) until
    // task 1 has started, which it can only on the other thread.
    tasks.emplace_back([&] {
      ++runs[0];
      first_two[0] = std::this_thread::get_id();
      spin_until(second_started);
    });
    tasks.emplace_back([&] {
      ++runs[1];
      first_two[1] = std::this_thread::get_id();
      second_started = true;
      // A task asking for the helpers gets none: they are held by its caller.
      const std::function<void()> inner[] = {[&] { ++inner_ran; }, [&] { ++inner_ran; }};
      nested_refused = !try_run_on_helpers(inner);
      run_on_helpers(inner);  // in turn, here
    });
    for (std::size_t k = 2; k < runs.size(); ++k) tasks.emplace_back([&, k] { ++runs[k]; });
    ASSERT_TRUE(try_run_on_helpers(tasks));
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1) << round;
    EXPECT_NE(first_two[0], first_two[1]) << round;
    EXPECT_TRUE(nested_refused) << round;
    EXPECT_EQ(inner_ran, 2) << round;
  }
  // On one thread the caller runs every task itself.
  set_solve_threads(1);
  std::vector<std::thread::id> ran(3);
  const std::function<void()> alone[] = {[&] { ran[0] = std::this_thread::get_id(); },
                                         [&] { ran[1] = std::this_thread::get_id(); },
                                         [&] { ran[2] = std::this_thread::get_id(); }};
  ASSERT_TRUE(try_run_on_helpers(alone));
  for (const auto& id : ran) EXPECT_EQ(id, std::this_thread::get_id());
}

TEST(SolveThreads, AChildForkedAfterTheHelpersRanGetsHelpersOfItsOwn) {
  const ThreadsScope scope(2);
  const std::function<void()> warm[] = {[] {}, [] {}};
  ASSERT_TRUE(try_run_on_helpers(warm));
  EXPECT_TRUE(true_in_child([] {
    // The parent's helper threads are not in the child: waiting on them would never end.
    // Task 0 waits (5 s at most) for task 1 to start: on a second thread, the child's own.
    std::atomic<bool> second{false};
    std::atomic<int> ran{0};
    const std::function<void()> tasks[] = {[&] {
                                             ++ran;
                                             spin_until(second);
                                           },
                                           [&] {
                                             ++ran;
                                             second = true;
                                           }};
    const auto start = std::chrono::steady_clock::now();
    return try_run_on_helpers(tasks) && ran == 2 &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(4);
  }));
}

TEST(SolveThreads, UsableCpusAreTheOnesTheProcessIsAllowed) {
  // In a child, so that this process keeps its CPUs: allowed one, it counts one.
  EXPECT_TRUE(true_in_child([] {
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(current_cpu(), &one);
    return sched_setaffinity(0, sizeof one, &one) == 0 && usable_cpus() == 1;
  }));
}

TEST(SolveThreads, TwoThreadsGiveTheSameSolveBitForBit) {
  std::mt19937_64 rng(4);
  std::vector<Keyframe> k;
  for (int i = 0; i < 900; ++i) k.push_back(test::random_keyframe(rng, 2, 0, 600));
  const RbfInterpolator one(k, 2, {}, 30.0);
  std::unique_ptr<RbfInterpolator> two;
  {
    const ThreadsScope scope(2);
    two = std::make_unique<RbfInterpolator>(k, 2, InterpolationSettings{}, 30.0);
  }
  EXPECT_EQ(one.diagnostics().max_residual, two->diagnostics().max_residual);
  EXPECT_EQ(one.diagnostics().condition_estimate, two->diagnostics().condition_estimate);
  for (int i = 0; i < 50; ++i) {
    const Direction d = test::random_direction(rng);
    const auto f = static_cast<std::int64_t>(rng() % 601);
    ASSERT_EQ(one.evaluate(d, f), two->evaluate(d, f)) << i;
  }
}

TEST(SolveThreads, TheKernelMatrixIsTheSameAndExactlySymmetricOnTwoThreads) {
  // 700 centres: the lower triangle computed, the upper one mirrored in tiles, both split.
  std::mt19937_64 rng(9);
  std::vector<Keyframe> k;
  for (int i = 0; i < 700; ++i) k.push_back(test::random_keyframe(rng, 1, 0, 900));
  const RbfPoints points = merge_keyframes(k, 1);
  const RbfKernel kernel = RbfKernel::from(InterpolationSettings{}, 30.0);
  const Eigen::MatrixXd one = kernel_matrix(points, kernel);
  Eigen::MatrixXd two;
  {
    const ThreadsScope scope(2);
    two = kernel_matrix(points, kernel);
  }
  ASSERT_EQ(one.rows(), 700);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, Eigen::MatrixXd(one.transpose()));
  // An entry above the diagonal is phi of its pair, as one row computed alone gives it.
  Eigen::ArrayXd row(700);
  kernel_row(points, kernel, points.unit(3), points.t[3], row);
  for (int j = 0; j < 700; ++j) ASSERT_EQ(one(3, j), row[j]) << j;
}

TEST(SolveThreads, AFactorTheConditionEstimateRejectsFallsBackAlikeOnTwoThreads) {
  // 40 pairs of keyframes 1e-10 degrees apart with different values: the Cholesky factorisation
  // of the projected block succeeds, its condition estimate (about 1e13) rejects it, and the LU
  // takes over. On two threads the estimate runs beside the first solve, which is then redone.
  std::vector<Keyframe> k;
  for (int i = 0; i < 40; ++i) {
    const Keyframe a{Direction{-175.0 + i * 9.0, 0.0}, 0, {static_cast<double>(i % 3)}};
    Keyframe b = a;
    b.direction.azimuth_deg += 1e-10;
    b.params = {static_cast<double>((i + 1) % 3)};
    k.push_back(a);
    k.push_back(b);
  }
  const RbfInterpolator one(k, 1, {}, 30.0);
  std::unique_ptr<RbfInterpolator> two;
  {
    const ThreadsScope scope(2);
    two = std::make_unique<RbfInterpolator>(k, 1, InterpolationSettings{}, 30.0);
  }
  EXPECT_EQ(one.diagnostics().method, RbfSolveMethod::NullSpaceLu);
  EXPECT_EQ(two->diagnostics().method, RbfSolveMethod::NullSpaceLu);
  EXPECT_GT(two->diagnostics().condition_estimate, 1e12);
  EXPECT_EQ(one.diagnostics().max_residual, two->diagnostics().max_residual);
  EXPECT_EQ(one.diagnostics().condition_estimate, two->diagnostics().condition_estimate);
  for (int i = 0; i < 40; ++i) {
    const Direction d{-175.0 + i * 9.0 + 4.5, 10.0};
    ASSERT_EQ(one.evaluate(d, 0), two->evaluate(d, 0)) << i;
  }
}

}  // namespace
}  // namespace vdfx::effects
