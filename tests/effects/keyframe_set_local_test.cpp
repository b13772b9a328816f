/// @file
/// @brief KeyframeSet with local interpolation in time: every edit re-solves only the windows it
/// changes and gives exactly what a fresh solve of the same keyframes gives; clones share the
/// windows; crossing the automatic threshold switches schemes.
#include <gtest/gtest.h>

#include <random>

#include "effects/keyframe_set.h"
#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

constexpr int kDim = 2;
constexpr double kFps = 30.0;

InterpolationSettings reach(double seconds) {
  InterpolationSettings s;
  s.reach_s = seconds;
  return s;
}

KeyframeSetOptions sync() {
  KeyframeSetOptions o;
  o.async = false;
  return o;
}

/// The set's published solution against a fresh RbfInterpolator of its keyframes, at random
/// views and every keyframe: they must be the same numbers.
void expect_same_as_fresh(const KeyframeSet& set, const InterpolationSettings& s,
                          std::uint64_t seed) {
  const RbfInterpolator fresh(set.keyframes(), kDim, s, kFps);
  const auto sol = set.solution();
  ASSERT_EQ(sol->local(), fresh.local());
  if (fresh.local()) {
    ASSERT_EQ(sol->layout(), fresh.layout());
  }
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> f(-10, 3100);
  for (int i = 0; i < 60; ++i) {
    const Direction d = test::random_direction(rng);
    const std::int64_t fr = f(rng);
    ASSERT_EQ(sol->evaluate(d, fr), fresh.evaluate(d, fr)) << "view " << i << " frame " << fr;
  }
  for (const Keyframe& k : set.keyframes())
    ASSERT_EQ(sol->evaluate(k.direction, k.frame), fresh.evaluate(k.direction, k.frame));
}

std::vector<Keyframe> random_set(int n, std::uint64_t seed, std::int64_t hi = 2999) {
  std::mt19937_64 rng(seed);
  std::vector<Keyframe> k;
  for (int i = 0; i < n; ++i) k.push_back(test::random_keyframe(rng, kDim, 0, hi));
  return k;
}

TEST(KeyframeSetLocal, EveryEditEqualsAFreshSolveAndTouchesFewWindows) {
  const InterpolationSettings s = reach(2.0);  // windows of 60 frames
  KeyframeSet set(kDim, s, kFps, random_set(500, 1), sync());
  ASSERT_TRUE(set.local());
  const int windows = set.solution()->layout().count;
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<int> op(0, 4);
  std::uint64_t solved_before = 0;
  for (int step = 0; step < 40; ++step) {
    std::uniform_int_distribution<std::size_t> pick(0, set.keyframes().size() - 1);
    bool incremental = true;
    switch (op(rng)) {
      case 0:
      case 1: incremental = set.add(test::random_keyframe(rng, kDim, 0, 2999)).incremental; break;
      case 2: set.remove(pick(rng)); break;
      case 3: {
        const std::size_t i = pick(rng);
        const std::int64_t frame = std::clamp<std::int64_t>(
            set.keyframes()[i].frame + static_cast<std::int64_t>(rng() % 41) - 20, 0, 2999);
        incremental = set.move(i, test::random_direction(rng), frame).incremental;
        break;
      }
      case 4: set.set_params(pick(rng), {0.25, 3.75}); break;
    }
    ASSERT_EQ(set.solution_version(), set.version());
    expect_same_as_fresh(set, s, static_cast<std::uint64_t>(step));
    ASSERT_TRUE(incremental) << "step " << step;
    // A keyframe lies in the data of at most four windows: an edit re-solves at most eight
    // (its place before and after), never all of them.
    const std::uint64_t solved = set.stats().windows_solved - solved_before;
    EXPECT_LE(solved, 8u) << "step " << step;
    EXPECT_GE(solved, 1u) << "step " << step;
    solved_before = set.stats().windows_solved;
  }
  EXPECT_EQ(set.stats().local_edits, 40u);
  EXPECT_GT(windows, 40);
}

TEST(KeyframeSetLocal, CloneSharesTheWindowsAndEditsApart) {
  const InterpolationSettings s = reach(1.0);
  KeyframeSet set(kDim, s, kFps, random_set(300, 3), sync());
  const auto clone = set.clone(sync());
  EXPECT_TRUE(clone->stats().cloned_exact);
  ASSERT_TRUE(clone->local());
  EXPECT_EQ(clone->solution()->windows()[3].get(), set.solution()->windows()[3].get());
  clone->add({{10.0, 5.0}, 1500, {1.0, 2.0}});
  EXPECT_EQ(set.keyframes().size(), 300u);
  EXPECT_EQ(clone->keyframes().size(), 301u);
  expect_same_as_fresh(*clone, s, 4);
  expect_same_as_fresh(set, s, 5);
}

TEST(KeyframeSetLocal, ALayoutChangeSolvesAfresh) {
  // Explicit reach: the span growing past a window adds windows and keeps the others.
  const InterpolationSettings s = reach(1.0);
  KeyframeSet set(kDim, s, kFps, random_set(200, 6, 1000), sync());
  const int before = set.solution()->layout().count;
  EXPECT_TRUE(set.add({{0.0, 0.0}, 2900, {1.0, 1.0}}).incremental);
  EXPECT_GT(set.solution()->layout().count, before);
  expect_same_as_fresh(set, s, 7);
  // Removing every keyframe but one, then all: a one-window set, then the empty (global) one.
  while (set.keyframes().size() > 1) set.remove(0);
  expect_same_as_fresh(set, s, 8);
  set.remove(0);
  EXPECT_FALSE(set.local());
  EXPECT_TRUE(set.solution()->empty());
}

TEST(KeyframeSetLocal, CrossingTheAutomaticThresholdSwitchesToLocal) {
  // 4096 keyframes are solved globally; the 4097th makes the set local (automatic reach), and
  // removing it makes it global again. The threshold counts keyframes: 512 places each keyed 8
  // times (merged into one centre) keep the solves small.
  std::vector<Keyframe> initial;
  for (const Keyframe& k : random_set(static_cast<int>(kGlobalSolveMaxKeyframes / 8), 9, 40000))
    initial.insert(initial.end(), 8, k);
  KeyframeSet set(kDim, {}, kFps, initial, sync());
  EXPECT_FALSE(set.local());
  EXPECT_EQ(set.solution()->centres(), 512);
  const auto e = set.add({{20.0, 10.0}, 777, {2.0, 2.0}});
  EXPECT_FALSE(e.incremental);
  ASSERT_TRUE(set.local());
  EXPECT_TRUE(set.solution()->layout().automatic);
  expect_same_as_fresh(set, {}, 10);
  // Later edits stay local and incremental.
  EXPECT_TRUE(set.add({{-20.0, 10.0}, 30000, {1.0, 3.0}}).incremental);
  expect_same_as_fresh(set, {}, 11);
  set.remove(set.keyframes().size() - 1);
  set.remove(set.keyframes().size() - 1);
  EXPECT_FALSE(set.local());
  expect_same_as_fresh(set, {}, 12);
}

}  // namespace
}  // namespace vdfx::effects
