/// @file
/// @brief The pending edit's incremental interpolant: a few hundred keyframes and a pending
/// keyframe that moves every frame (placement and grab) give what a fresh solve of the same
/// keyframes gives, to 1e-9, seeded once by a clone (no solve); landing on a keyframe leaves it
/// out and moving off brings it back; versions; commit. Also through the Editor with head turns.
#include <gtest/gtest.h>

#include <random>

#include "app/editor/editor.h"
#include "app/editor/pending_edit.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::Direction;
using effects::EffectType;
using effects::Keyframe;

constexpr std::int64_t kFrames = 90;

std::vector<Keyframe> random_keyframes(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), stops(-3.0, 3.0);
  std::uniform_int_distribution<std::int64_t> frame(0, kFrames - 1);
  std::vector<Keyframe> ks;
  for (int i = 0; i < n; ++i)
    ks.push_back({{170.0 * u(rng), std::asin(0.95 * u(rng)) * effects::kRadToDeg},
                  frame(rng),
                  {stops(rng)}});
  return ks;
}

/// Largest difference between `rbf` and a fresh solve of the pending edit's keyframes over a
/// spread of directions and frames.
double max_difference(const effects::RbfInterpolator& rbf, const PendingEdit& p,
                      const Document& doc) {
  const effects::RbfInterpolator fresh(p.keyframe_list(), p.target().dimension(),
                                       doc.interpolation(p.target()), doc.video().fps,
                                       p.target().neutral());
  double worst = 0.0;
  for (int i = 0; i < 24; ++i) {
    const Direction d{-172.0 + 15.0 * i, -80.0 + 7.0 * i};
    const std::int64_t f = (i * 7) % kFrames;
    worst = std::max(worst, (rbf.evaluate(d, f) - fresh.evaluate(d, f)).cwiseAbs().maxCoeff());
  }
  return worst;
}

io::Sidecar with_exposure(std::vector<Keyframe> ks) {
  io::Sidecar sc = test::empty_sidecar(kFrames);
  sc.effects.push_back({EffectType::Exposure, std::nullopt, std::move(ks)});
  return sc;
}

class PendingPath : public ::testing::TestWithParam<bool> {};  // grab (true) or placement

TEST_P(PendingPath, EveryStepEqualsAFreshSolveWithOneSeedAndNoSolve) {
  Document doc(with_exposure(random_keyframes(300, 7u)), {{.async = false}});
  const bool grab = GetParam();
  Keyframe key{{10.0, 5.0}, 40, {2.5}};
  if (grab) key.params = doc.keyframes(EffectType::Exposure)[17].params;
  PendingEdit& p = doc.begin_pending(EffectType::Exposure,
                                     grab ? std::optional<std::size_t>(17) : std::nullopt, key);
  for (int step = 0; step < 12; ++step) {
    key.direction = {effects::wrap_azimuth_deg(10.0 + 3.7 * step), 5.0 + 1.3 * step};
    if (grab) key.frame = 40 + step % 3;  // the playhead moves too
    p.set_key(key);
    const auto rbf = p.interpolant();
    ASSERT_TRUE(rbf);
    EXPECT_LT(max_difference(*rbf, p, doc), 1e-9) << "step " << step;
  }
  EXPECT_EQ(doc.pending_stats().seeds, 1u);
  EXPECT_EQ(doc.pending_stats().full_seeds, 0u)
      << "the document's solved set is cloned, not re-solved";
  EXPECT_EQ(doc.pending_stats().moves, 11u);
  // The values change (the widget while placing): no new seed.
  key.params = {-1.5};
  p.set_key(key);
  EXPECT_LT(max_difference(*p.interpolant(), p, doc), 1e-9);
  EXPECT_EQ(doc.pending_stats().seeds, 1u);
  // Committed: the document holds what the pending edit showed.
  const std::size_t before = doc.keyframes(EffectType::Exposure).size();
  ASSERT_TRUE(doc.commit_pending());
  EXPECT_FALSE(doc.pending());
  EXPECT_EQ(doc.keyframes(EffectType::Exposure).size(), before + (grab ? 0u : 1u));
}

INSTANTIATE_TEST_SUITE_P(Editor, PendingPath, ::testing::Values(false, true), [](const auto& info) {
  return std::string(info.param ? "grab" : "placement");
});

TEST(PendingEdit, LandingOnAKeyframeLeavesItOutAndMovingOffBringsItBack) {
  std::vector<Keyframe> ks = random_keyframes(40, 3u);
  ks.push_back({{50.0, 0.0}, 20, {3.0}});
  Document doc(with_exposure(ks), {{.async = false}});
  PendingEdit& p = doc.begin_pending(EffectType::Exposure, std::nullopt, {{45.0, 0.0}, 20, {-2.0}});
  p.interpolant();
  p.set_key({{50.2, 0.0}, 20, {-2.0}});  // within 0.5 deg of the last keyframe, same frame
  ASSERT_EQ(p.keyframe_list().size(), ks.size());  // it replaces that one
  EXPECT_LT(max_difference(*p.interpolant(), p, doc), 1e-9);
  EXPECT_NEAR(p.interpolant()->evaluate(Direction{50.0, 0.0}, 20)[0], -2.0, 0.05);
  p.set_key({{55.0, 0.0}, 20, {-2.0}});
  ASSERT_EQ(p.keyframe_list().size(), ks.size() + 1);
  const auto rbf = p.interpolant();
  EXPECT_LT(max_difference(*rbf, p, doc), 1e-9);
  EXPECT_NEAR(rbf->evaluate(Direction{50.0, 0.0}, 20)[0], 3.0, 1e-9);  // back
  EXPECT_EQ(doc.pending_stats().full_seeds, 0u);
}

TEST(PendingEdit, DocumentEditsReseedAndOtherChangesDoNot) {
  Document doc(with_exposure(random_keyframes(30, 5u)), {{.async = false}});
  PendingEdit& p = doc.begin_pending(EffectType::Exposure, std::nullopt, {{0.0, 0.0}, 10, {1.0}});
  p.interpolant();
  doc.set_params(EffectType::Exposure, {0.5});  // the chosen values: the keyframes did not change
  p.interpolant();
  EXPECT_EQ(doc.pending_stats().seeds, 1u);
  doc.set_keyframe_params(EffectType::Exposure, 3, {2.75});
  EXPECT_LT(max_difference(*p.interpolant(), p, doc), 1e-9);
  EXPECT_EQ(doc.pending_stats().seeds, 2u);
  auto s = doc.interpolation(EffectType::Exposure);
  s.exponent = 1.5;
  doc.set_interpolation(EffectType::Exposure, s);
  EXPECT_LT(max_difference(*p.interpolant(), p, doc), 1e-9);
  EXPECT_EQ(doc.pending_stats().seeds, 3u);
}

TEST(PendingEdit, ASetWithoutAnExactStateIsSolvedOnceAndVersionsOnlyGrow) {
  // Two keyframes at one place and frame merge into one centre: the document's set has no exact
  // incremental state to clone, so the seed solves (counted), and then moves incrementally.
  std::vector<Keyframe> ks = random_keyframes(20, 9u);
  ks.push_back(ks.front());
  Document doc(with_exposure(ks), {{.async = false}});
  PendingEdit& p = doc.begin_pending(EffectType::Exposure, std::nullopt, {{12.0, 3.0}, 15, {1.0}});
  const std::uint64_t v0 = p.version();
  EXPECT_GT(v0, 0u);
  EXPECT_LT(max_difference(*p.interpolant(), p, doc), 1e-9);
  EXPECT_EQ(doc.pending_stats().full_seeds, 1u);
  p.set_key({{14.0, 3.0}, 15, {1.0}});
  EXPECT_GT(p.version(), v0);
  const std::uint64_t v1 = p.version();
  p.set_key({{14.0, 3.0}, 15, {1.0}});  // no change: no new version
  EXPECT_EQ(p.version(), v1);
  doc.cancel_pending();
  // A later pending edit of the same document never reuses a version (caches key on them).
  EXPECT_GT(
      doc.begin_pending(EffectType::Exposure, std::nullopt, {{14.0, 3.0}, 15, {1.0}}).version(),
      v1);
}

TEST(PendingEdit, AHeldKeyframeAtItsPlaceChangesNothing) {
  Document doc(with_exposure(random_keyframes(10, 2u)), {{.async = false}});
  const Keyframe k = doc.keyframes(EffectType::Exposure)[4];
  PendingEdit& p = doc.begin_pending(EffectType::Exposure, 4, k);
  EXPECT_FALSE(p.changes_interpolant());
  EXPECT_EQ(p.version(), 0u);
  EXPECT_EQ(p.interpolant(), nullptr);
  p.set_key({{k.direction.azimuth_deg + 3.0, k.direction.altitude_deg}, k.frame, k.params});
  EXPECT_TRUE(p.changes_interpolant());
  EXPECT_GT(p.version(), 0u);
  EXPECT_LT(max_difference(*p.interpolant(), p, doc), 1e-9);
}

TEST(EditorPreview, HeadTurnsWhilePlacingAndGrabbingMatchAFreshSolve) {
  io::Sidecar sc = test::empty_sidecar(kFrames);
  sc.effects.push_back({EffectType::Exposure, std::nullopt, random_keyframes(200, 11u)});
  Editor ed(sc, DocumentOptions{{.async = false}}, EditorOptions{});
  ed.set_chosen_params({2.0});
  ed.seek(30);
  const auto settings = ed.document().interpolation(EffectType::Exposure);
  auto expect_fresh = [&](const Keyframe& key) {
    const PendingEdit* p = ed.document().pending();
    ASSERT_TRUE(p);
    EXPECT_EQ(p->key(), key);
    const effects::RbfInterpolator fresh(p->keyframe_list(), 1, settings, 30.0);
    for (const Direction d :
         {Direction{-120.0, 10.0}, Direction{75.0, -40.0}, Direction{170.0, 60.0}})
      EXPECT_NEAR(ed.params_for_view(d, 30).exposure_stops,
                  std::clamp(fresh.evaluate(d, 30)[0], -8.0, 8.0), 1e-9);
  };
  std::int64_t t = 0;
  xr::ActionSync sync;                    // the edges InputBackend::poll would add
  for (int step = 0; step < 6; ++step) {  // trigger held: preview a new keyframe
    t += 33'333'333;
    auto in = test::looking(20.0 + 4.0 * step, 2.0 * step, t);
    in.right.trigger = 1.0;
    ed.update(sync.sync(in), t);
    ASSERT_TRUE(ed.previewing());
    expect_fresh({ed.view_direction(), 30, {2.0}});
  }
  t += 33'333'333;
  ed.update(sync.sync(test::looking(40.0, 10.0, t)), t);  // release: placed
  ASSERT_FALSE(ed.previewing());
  for (int step = 0; step < 6; ++step) {  // squeeze held: grab the nearest (the one just placed)
    t += 33'333'333;
    auto in = test::looking(40.0 - 5.0 * step, 10.0 - step, t);
    in.right.squeeze = 1.0;
    ed.update(sync.sync(in), t);
    ASSERT_TRUE(ed.grabbing());
    expect_fresh(*ed.selected_preview());
  }
  // Both previews were seeded from the document's exact set: no full solve on the frame thread.
  EXPECT_EQ(ed.document().pending_stats().seeds, 2u);
  EXPECT_EQ(ed.document().pending_stats().full_seeds, 0u);
}

}  // namespace
}  // namespace vdfx::app
