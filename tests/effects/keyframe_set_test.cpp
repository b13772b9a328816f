/// @file
/// @brief KeyframeSet: replace-on-top, incremental updates equal full solves, async re-solves.
#include "effects/keyframe_set.h"

#include <gtest/gtest.h>

#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

constexpr int kDim = 2;

/// Largest difference between two interpolants at 25 random views (frames 0..200).
double max_diff(const RbfInterpolator& a, const RbfInterpolator& b, std::mt19937_64& rng) {
  double worst = 0.0;
  std::uniform_int_distribution<std::int64_t> f(0, 200);
  for (int i = 0; i < 25; ++i) {
    const Direction d = test::random_direction(rng);
    const std::int64_t fr = f(rng);
    worst = std::max(worst, (a.evaluate(d, fr) - b.evaluate(d, fr)).cwiseAbs().maxCoeff());
  }
  return worst;
}

double max_diff(const RbfInterpolator& a, const RbfInterpolator& b, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return max_diff(a, b, rng);
}

/// Max difference between the set's published solution and a fresh full solve, at random views.
double max_diff_to_full_solve(const KeyframeSet& set, std::mt19937_64& rng) {
  const RbfInterpolator fresh(set.keyframes(), kDim, {}, 30.0);
  const auto sol = set.solution();
  double worst = max_diff(*sol, fresh, rng);
  for (const Keyframe& k : set.keyframes())  // and every keyframe is reproduced
    worst = std::max(worst, (sol->evaluate(k.direction, k.frame) -
                             Eigen::Map<const Eigen::VectorXd>(k.params.data(), kDim))
                                .cwiseAbs()
                                .maxCoeff());
  return worst;
}

TEST(KeyframeSet, IncrementalEditsMatchAFullSolve) {
  std::mt19937_64 rng(5);
  std::vector<Keyframe> initial;
  for (int i = 0; i < 60; ++i) initial.push_back(test::random_keyframe(rng, kDim, 0, 200));
  KeyframeSetOptions opt;
  opt.async = false;
  KeyframeSet set(kDim, {}, 30.0, initial, opt);
  int incremental = 0, edits = 0;
  std::uniform_int_distribution<int> op(0, 3);
  for (int step = 0; step < 60; ++step, ++edits) {
    std::uniform_int_distribution<size_t> pick(0, set.keyframes().size() - 1);
    switch (op(rng)) {
      case 0:
      case 1: incremental += set.add(test::random_keyframe(rng, kDim, 0, 200)).incremental; break;
      case 2: set.remove(pick(rng)); break;
      case 3: {
        const size_t i = pick(rng);
        incremental +=
            set.move(i, test::random_direction(rng), set.keyframes()[i].frame).incremental;
        set.set_params(i, {0.5, 3.5});
        break;
      }
    }
    ASSERT_EQ(set.solution_version(), set.version()) << "sync mode publishes every edit";
    ASSERT_LE(max_diff_to_full_solve(set, rng), 1e-9) << "after edit " << step;
  }
  EXPECT_GT(incremental, edits / 3) << "adds and moves should mostly avoid a full solve";
}

TEST(KeyframeSet, SkippingTheRefinementGivesTheSameResultAsAlwaysRefining) {
  std::mt19937_64 rng(21);
  std::vector<Keyframe> initial;
  // 20 keyframes: some updates already meet the refinement threshold, some do not.
  for (int i = 0; i < 20; ++i) initial.push_back(test::random_keyframe(rng, kDim, 0, 200));
  KeyframeSetOptions lazy, eager;
  lazy.async = eager.async = false;
  eager.always_refine = true;
  KeyframeSet a(kDim, {}, 30.0, initial, lazy), b(kDim, {}, 30.0, initial, eager);
  std::mt19937_64 edits(22);
  for (int step = 0; step < 40; ++step) {
    if (step % 2 == 1) {
      const size_t i = static_cast<size_t>(step) % a.keyframes().size();
      a.remove(i);
      b.remove(i);
    } else {
      const Keyframe k = test::random_keyframe(edits, kDim, 0, 200);
      a.add(k);
      b.add(k);
    }
    std::mt19937_64 views(static_cast<std::uint64_t>(step));
    for (int v = 0; v < 20; ++v) {
      const Direction d = test::random_direction(views);
      const std::int64_t f = static_cast<std::int64_t>(views() % 201);
      ASSERT_LE((a.solution()->evaluate(d, f) - b.solution()->evaluate(d, f)).cwiseAbs().maxCoeff(),
                1e-9)
          << "after edit " << step;
    }
  }
  ASSERT_LE(max_diff_to_full_solve(a, rng), 1e-9);
  const KeyframeSetStats sa = a.stats(), sb = b.stats();
  EXPECT_EQ(sb.refinements, sb.incremental_edits) << "always_refine refines every update";
  EXPECT_GT(sa.incremental_edits, 30u);
  EXPECT_GT(sa.refinements, 0u) << "and some should not";
  EXPECT_LT(sa.refinements, sa.incremental_edits) << "some updates should meet the threshold";
}

TEST(KeyframeSet, EditsReuseTheIncrementalStorage) {
  std::mt19937_64 rng(23);
  std::vector<Keyframe> initial;
  for (int i = 0; i < 100; ++i) initial.push_back(test::random_keyframe(rng, kDim, 0, 200));
  KeyframeSetOptions opt;
  opt.async = false;
  KeyframeSet set(kDim, {}, 30.0, initial, opt);
  const int capacity = set.stats().capacity;
  ASSERT_GT(capacity, 100 + 5) << "spare slots after a full solve";
  for (int i = 0; i < 200; ++i) {  // add/remove pairs: the size stays at 100-101
    set.add(test::random_keyframe(rng, kDim, 0, 200));
    set.remove(static_cast<size_t>(i) % set.keyframes().size());
  }
  EXPECT_EQ(set.stats().storage_growths, 0u);
  EXPECT_EQ(set.stats().capacity, capacity);
  EXPECT_EQ(set.stats().incremental_edits, 400u);
  // Growing past the spare slots reallocates (by half), and results stay exact.
  for (int i = 0; i < capacity - 100; ++i) set.add(test::random_keyframe(rng, kDim, 0, 200));
  EXPECT_GE(set.stats().storage_growths, 1u);
  EXPECT_GT(set.stats().capacity, capacity);
  EXPECT_LE(max_diff_to_full_solve(set, rng), 1e-9);
}

TEST(KeyframeSet, AddingOnTopOfAKeyframeReplacesIt) {
  KeyframeSetOptions opt;
  opt.async = false;
  KeyframeSet set(kDim, {}, 30.0, {{{10, 0}, 5, {1, 1}}, {{50, 0}, 5, {2, 2}}}, opt);
  const auto e = set.add({{10.3, 0.2}, 5, {3, 3}});  // 0.36 degrees away, same frame
  ASSERT_TRUE(e.replaced.has_value());
  EXPECT_EQ(*e.replaced, 0u);
  EXPECT_EQ(set.keyframes().size(), 2u);
  EXPECT_NEAR(set.solution()->evaluate(Direction{10.3, 0.2}, 5)[0], 3.0, 1e-9);
  EXPECT_FALSE(set.add({{10.3, 0.2}, 6, {4, 4}}).replaced);  // another frame
  EXPECT_FALSE(set.add({{11.0, 0.0}, 5, {4, 4}}).replaced);  // 1 degree away
  EXPECT_EQ(set.keyframes().size(), 4u);
  // Moving a keyframe onto another removes the one it lands on.
  const auto m = set.move(3, {50.1, 0}, 5);
  ASSERT_TRUE(m.replaced.has_value());
  EXPECT_EQ(set.keyframes().size(), 3u);
  EXPECT_NEAR(set.solution()->evaluate(Direction{50.1, 0}, 5)[0], 4.0, 1e-9);
}

TEST(KeyframeSet, ChangingTheActiveTermsForcesAFullSolve) {
  std::mt19937_64 rng(8);
  std::vector<Keyframe> k;
  for (int i = 0; i < 60; ++i) {
    k.push_back(test::random_keyframe(rng, kDim, 0, 0));  // all at frame 0: no t term
  }
  KeyframeSetOptions opt;
  opt.async = false;
  KeyframeSet set(kDim, {}, 30.0, k, opt);
  EXPECT_FALSE(set.solution()->basis().has(PolynomialBasis::T));
  EXPECT_TRUE(set.add(test::random_keyframe(rng, kDim, 0, 0)).incremental);
  const auto e = set.add(test::random_keyframe(rng, kDim, 50, 50));
  EXPECT_FALSE(e.incremental);
  EXPECT_TRUE(set.solution()->basis().has(PolynomialBasis::T));
  EXPECT_LE(max_diff_to_full_solve(set, rng), 1e-9);
}

TEST(KeyframeSet, AsyncFullSolveIsSwappedInAndReadersAlwaysHaveASolution) {
  std::mt19937_64 rng(9);
  std::vector<Keyframe> k;
  for (int i = 0; i < 300; ++i) k.push_back(test::random_keyframe(rng, kDim, 0, 0));
  KeyframeSetOptions opt;
  opt.inline_full_solve_max = 0;  // every full solve goes to the worker
  KeyframeSet set(kDim, {}, 30.0, k, opt);
  ASSERT_NE(set.solution(), nullptr);
  // A new frame adds the t term: a full re-solve, on the worker.
  const auto e = set.add(test::random_keyframe(rng, kDim, 40, 40));
  EXPECT_FALSE(e.incremental);
  const std::uint64_t v1 = set.version();
  set.add(test::random_keyframe(rng, kDim, 70, 70));  // edit while the worker may be busy
  const std::uint64_t v2 = set.version();
  ASSERT_NE(set.solution(), nullptr);
  ASSERT_TRUE(set.wait_for_version(v2, std::chrono::seconds(60)));
  EXPECT_GE(set.solution_version(), v1);
  EXPECT_EQ(set.solution()->centres(), 302);
  EXPECT_LE(max_diff_to_full_solve(set, rng), 1e-9);
  // After the worker's result is adopted, edits are incremental again.
  EXPECT_TRUE(set.add(test::random_keyframe(rng, kDim, 40, 70)).incremental);
  EXPECT_EQ(set.solution_version(), set.version());
}

TEST(KeyframeSet, CloneCopiesTheExactStateAndThenEditsLikeAFreshSolve) {
  std::mt19937_64 rng(31);
  std::vector<Keyframe> initial;
  for (int i = 0; i < 80; ++i) initial.push_back(test::random_keyframe(rng, kDim, 0, 200));
  KeyframeSetOptions opt;
  opt.async = false;
  KeyframeSet source(kDim, {}, 30.0, initial, opt);
  for (int i = 0; i < 5; ++i)
    ASSERT_TRUE(source.add(test::random_keyframe(rng, kDim, 0, 200)).incremental);
  source.set_params(3, {0.25, 3.0});
  const auto before = source.solution();
  const auto keyframes_before = source.keyframes();

  const auto clone = source.clone(opt);
  EXPECT_TRUE(clone->stats().cloned_exact) << "an exact source is copied, not solved";
  EXPECT_FALSE(source.stats().cloned_exact);
  EXPECT_EQ(clone->keyframes(), source.keyframes());
  EXPECT_EQ(clone->version(), source.version());
  EXPECT_EQ(clone->solution_version(), source.solution_version());
  EXPECT_LE(max_diff(*clone->solution(), *before, 1), 1e-12);
  EXPECT_EQ(clone->stats().capacity, source.stats().capacity);

  // The clone's edits are incremental (it has the state) and match a fresh solve; the source
  // is left alone.
  for (int step = 0; step < 12; ++step) {
    const size_t i = static_cast<size_t>(step * 7) % clone->keyframes().size();
    switch (step % 4) {
      case 0: EXPECT_TRUE(clone->add(test::random_keyframe(rng, kDim, 0, 200)).incremental); break;
      case 1:
        EXPECT_TRUE(
            clone->move(i, test::random_direction(rng), clone->keyframes()[i].frame).incremental);
        break;
      case 2: clone->set_params(i, {1.5, 2.5}); break;
      case 3: clone->remove(i); break;
    }
    ASSERT_LE(max_diff_to_full_solve(*clone, rng), 1e-9) << "after clone edit " << step;
  }
  EXPECT_EQ(clone->stats().incremental_edits, 12u)
      << "no edit of the clone fell back to a full solve";
  EXPECT_EQ(source.keyframes(), keyframes_before);
  EXPECT_EQ(source.solution(), before);
  // The source still edits correctly after being cloned.
  EXPECT_TRUE(source.add(test::random_keyframe(rng, kDim, 0, 200)).incremental);
  EXPECT_LE(max_diff_to_full_solve(source, rng), 1e-9);
}

TEST(KeyframeSet, CloneWithoutAnExactStateSolves) {
  // Two keyframes merged into one centre: no incremental state, so the clone solves.
  KeyframeSetOptions opt;
  opt.async = false;
  std::vector<Keyframe> k{{{10, 0}, 5, {1, 1}},   {{10, 0}, 5, {3, 3}},
                          {{60, 10}, 9, {2, 0}},  {{-40, -20}, 20, {0, 2}},
                          {{120, 30}, 2, {4, 1}}, {{-150, 5}, 14, {1, 4}}};
  KeyframeSet source(kDim, {}, 30.0, k, opt);
  ASSERT_EQ(source.stats().capacity, 0) << "the test needs a source without incremental state";
  const auto clone = source.clone(opt);
  EXPECT_FALSE(clone->stats().cloned_exact);
  EXPECT_EQ(clone->keyframes(), source.keyframes());
  EXPECT_LE(max_diff(*clone->solution(), *source.solution(), 2), 1e-12);
}

TEST(KeyframeSet, CloneOfAnAsyncSetAfterAWorkerSolve) {
  std::mt19937_64 rng(33);
  std::vector<Keyframe> k;
  for (int i = 0; i < 120; ++i) k.push_back(test::random_keyframe(rng, kDim, 0, 0));
  KeyframeSetOptions opt;
  opt.inline_full_solve_max = 0;  // full solves on the worker
  KeyframeSet source(kDim, {}, 30.0, k, opt);
  EXPECT_FALSE(
      source.add(test::random_keyframe(rng, kDim, 40, 40)).incremental);  // adds the t term
  {
    // Whether the worker has finished or not, the clone is complete and current.
    const auto early = source.clone(opt);
    EXPECT_EQ(early->solution_version(), source.version());
    EXPECT_LE(max_diff_to_full_solve(*early, rng), 1e-9);
  }
  ASSERT_TRUE(source.wait_for_version(source.version(), std::chrono::seconds(60)));
  // The worker's state was published but not adopted by an edit yet: the clone copies it.
  KeyframeSetOptions sync = opt;
  sync.async = false;
  const auto clone = source.clone(sync);
  EXPECT_TRUE(clone->stats().cloned_exact);
  EXPECT_LE(max_diff(*clone->solution(), *source.solution(), 3), 1e-12);
  EXPECT_TRUE(clone->add(test::random_keyframe(rng, kDim, 0, 40)).incremental);
  EXPECT_LE(max_diff_to_full_solve(*clone, rng), 1e-9);
}

}  // namespace
}  // namespace vdfx::effects
