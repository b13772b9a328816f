/// @file
/// @brief The live preview's incremental interpolant: a few hundred keyframes and a preview
/// keyframe that moves every frame (placement and grab) give what a fresh solve of the same
/// keyframes gives, to 1e-9, with one full solve per preview; landing on a keyframe leaves it
/// out and moving off brings it back. Also through the Editor with head turns.
#include <gtest/gtest.h>

#include <random>

#include "app/editor.h"
#include "app/editor_preview.h"
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
    ks.push_back({{170.0 * u(rng), std::asin(0.95 * u(rng)) * effects::kRadToDeg}, frame(rng), {stops(rng)}});
  return ks;
}

/// Largest difference between `rbf` and a fresh solve of the target's keyframes over a spread
/// of directions and frames.
double max_difference(const effects::RbfInterpolator& rbf, const PreviewTarget& t) {
  const effects::RbfInterpolator fresh(preview_keyframe_list(t), t.dimension, t.settings, t.fps, t.neutral);
  double worst = 0.0;
  for (int i = 0; i < 24; ++i) {
    const Direction d{-172.0 + 15.0 * i, -80.0 + 7.0 * i};
    const std::int64_t f = (i * 7) % kFrames;
    worst = std::max(worst, (rbf.evaluate(d, f) - fresh.evaluate(d, f)).cwiseAbs().maxCoeff());
  }
  return worst;
}

struct PathCase {
  const char* name;
  bool grab;
  bool source;  //!< seed from a solved KeyframeSet of the keyframes (as the editor does)
};

class PreviewPath : public ::testing::TestWithParam<PathCase> {};

TEST_P(PreviewPath, EveryStepEqualsAFreshSolveWithOneSeed) {
  const auto ks = random_keyframes(300, 7u);
  PreviewTarget t;
  t.keyframes = &ks;
  t.revision = 1;
  t.neutral = {0.0};
  Keyframe key{{10.0, 5.0}, 40, {2.5}};
  if (GetParam().grab) {
    t.moved = 17;
    key.params = ks[17].params;
  }
  const effects::KeyframeSet solved(1, {}, 30.0, ks, {.async = false}, {0.0});
  if (GetParam().source) t.source = &solved, t.keyframes = &solved.keyframes();
  PreviewInterpolant p({.async = false});
  for (int step = 0; step < 12; ++step) {
    key.direction = {effects::wrap_azimuth_deg(10.0 + 3.7 * step), 5.0 + 1.3 * step};
    if (GetParam().grab) key.frame = 40 + step % 3;  // the playhead moves too
    t.key = key;
    const auto rbf = p.update(t);
    ASSERT_TRUE(rbf);
    EXPECT_LT(max_difference(*rbf, t), 1e-9) << "step " << step;
  }
  EXPECT_EQ(p.seeds(), 1u);
  EXPECT_EQ(p.full_seeds(), GetParam().source ? 0u : 1u) << "a solved source is cloned, not re-solved";
  EXPECT_EQ(p.moves(), 11u);
  // The values change (the widget while previewing): no new seed.
  t.key.params = {-1.5};
  EXPECT_LT(max_difference(*p.update(t), t), 1e-9);
  EXPECT_EQ(p.seeds(), 1u);
}

INSTANTIATE_TEST_SUITE_P(Editor, PreviewPath, ::testing::Values(PathCase{"placement", false, false}, PathCase{"grab", true, false},
                                                           PathCase{"placement_from_source", false, true},
                                                           PathCase{"grab_from_source", true, true}),
                         [](const auto& info) { return std::string(info.param.name); });

class PreviewLanding : public ::testing::TestWithParam<bool> {};

TEST_P(PreviewLanding, LandingOnAKeyframeLeavesItOutAndMovingOffBringsItBack) {
  std::vector<Keyframe> ks = random_keyframes(40, 3u);
  ks.push_back({{50.0, 0.0}, 20, {3.0}});
  const effects::KeyframeSet solved(1, {}, 30.0, ks, {.async = false}, {0.0});
  PreviewTarget t;
  if (GetParam()) t.source = &solved;  // the seeds clone it and remove the replaced keyframe
  t.keyframes = GetParam() ? &solved.keyframes() : &ks;
  t.neutral = {0.0};
  t.key = {{45.0, 0.0}, 20, {-2.0}};
  PreviewInterpolant p({.async = false});
  p.update(t);
  t.key.direction = {50.2, 0.0};  // within 0.5 deg of the last keyframe, same frame
  ASSERT_EQ(preview_keyframe_list(t).size(), ks.size());  // it replaces that one
  EXPECT_LT(max_difference(*p.update(t), t), 1e-9);
  EXPECT_NEAR(p.update(t)->evaluate(Direction{50.0, 0.0}, 20)[0], -2.0, 0.05);
  t.key.direction = {55.0, 0.0};
  ASSERT_EQ(preview_keyframe_list(t).size(), ks.size() + 1);
  const auto rbf = p.update(t);
  EXPECT_LT(max_difference(*rbf, t), 1e-9);
  EXPECT_NEAR(rbf->evaluate(Direction{50.0, 0.0}, 20)[0], 3.0, 1e-9);  // back
  EXPECT_EQ(p.full_seeds(), GetParam() ? 0u : p.seeds());
}

INSTANTIATE_TEST_SUITE_P(Editor, PreviewLanding, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "from_source" : "solved"); });

TEST(PreviewInterpolant, DocumentEditsReseedAndOtherRevisionsDoNot) {
  std::vector<Keyframe> ks = random_keyframes(30, 5u);
  PreviewTarget t;
  t.keyframes = &ks;
  t.revision = 1;
  t.neutral = {0.0};
  t.key = {{0.0, 0.0}, 10, {1.0}};
  PreviewInterpolant p({.async = false});
  p.update(t);
  t.revision = 2;  // e.g. the chosen values changed: the keyframes did not
  p.update(t);
  EXPECT_EQ(p.seeds(), 1u);
  ks[3].params = {2.75};
  t.revision = 3;
  EXPECT_LT(max_difference(*p.update(t), t), 1e-9);
  EXPECT_EQ(p.seeds(), 2u);
  t.settings.exponent = 1.5;
  EXPECT_LT(max_difference(*p.update(t), t), 1e-9);
  EXPECT_EQ(p.seeds(), 3u);
}

TEST(EditorPreview, HeadTurnsWhilePlacingAndGrabbingMatchAFreshSolve) {
  io::Sidecar sc = test::empty_sidecar(kFrames);
  sc.effects.push_back({EffectType::Exposure, std::nullopt, random_keyframes(200, 11u)});
  Editor ed(sc, DocumentOptions{{.async = false}}, EditorOptions{});
  ed.set_chosen_params({2.0});
  ed.seek(30);
  const auto settings = ed.document().interpolation(EffectType::Exposure);
  auto expect_fresh = [&](std::vector<Keyframe> ks, const Keyframe& key, std::optional<std::size_t> moved) {
    PreviewTarget t;
    t.keyframes = &ks;
    t.moved = moved;
    t.key = key;
    t.neutral = {0.0};
    t.settings = settings;
    const effects::RbfInterpolator fresh(preview_keyframe_list(t), 1, settings, 30.0);
    for (const Direction d : {Direction{-120.0, 10.0}, Direction{75.0, -40.0}, Direction{170.0, 60.0}})
      EXPECT_NEAR(ed.params_for_view(d, 30).exposure_stops, std::clamp(fresh.evaluate(d, 30)[0], -8.0, 8.0), 1e-9);
  };
  std::int64_t t = 0;
  xr::ActionSync sync;  // the edges InputBackend::poll would add
  for (int step = 0; step < 6; ++step) {  // trigger held: preview a new keyframe
    t += 33'333'333;
    auto in = test::looking(20.0 + 4.0 * step, 2.0 * step, t);
    in.right.trigger = 1.0;
    ed.update(sync.sync(in), t);
    ASSERT_TRUE(ed.previewing());
    expect_fresh(ed.document().keyframes(EffectType::Exposure), {ed.view_direction(), 30, {2.0}}, std::nullopt);
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
    expect_fresh(ed.document().keyframes(EffectType::Exposure), *ed.selected_preview(), ed.selected_keyframe());
  }
  // Both previews were seeded from the document's exact set: no full solve on the frame thread.
  EXPECT_EQ(ed.preview().seeds(), 2u);
  EXPECT_EQ(ed.preview().full_seeds(), 0u);
}

}  // namespace
}  // namespace vdfx::app
