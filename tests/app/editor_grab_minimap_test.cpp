/// @file
/// @brief While a keyframe is held by the grab, the minimap field is the live preview's
/// interpolant (synchronously, and through the MinimapWorker with async visualizations), and
/// the document's again after release or cancel.
#include <gtest/gtest.h>

#include <random>

#include "app/editor/editor.h"
#include "app/editor/visualizations.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::Direction;
using effects::EffectType;
using effects::Keyframe;

io::Sidecar forty_keyframes() {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> az(-170.0, 170.0), alt(-60.0, 60.0), stops(-3.0, 3.0);
  std::vector<Keyframe> ks;
  for (int i = 0; i < 40; ++i) ks.push_back({{az(rng), alt(rng)}, 30, {stops(rng)}});
  ks.push_back({{0.0, 0.0}, 30, {3.0}});  // the one the head looks at: grabbed
  io::Sidecar sc = test::empty_sidecar(90);
  sc.effects.push_back({EffectType::Exposure, std::nullopt, ks});
  return sc;
}

/// The minimap a fresh solve of `keyframes` gives at frame 30.
cv::Mat expected_field(const std::vector<Keyframe>& keyframes,
                       const effects::InterpolationSettings& s) {
  const effects::RbfInterpolator rbf(keyframes, 1, s, 30.0, {0.0});
  return effect_minimap(&rbf, EffectType::Exposure, 30, 128, 64);
}

double max_abs(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}

struct Case {
  const char* name;
  bool async;
};
class GrabMinimap : public ::testing::TestWithParam<Case> {};

TEST_P(GrabMinimap, FieldFollowsTheHeldKeyframe) {
  EditorOptions eo;
  eo.visuals.async = GetParam().async;
  Editor ed(forty_keyframes(), DocumentOptions{{.async = false}}, eo);
  ed.seek(30);
  std::int64_t t = 0;
  xr::ActionSync sync;
  auto frame = [&](double az, double alt, double squeeze) {
    t += 33'333'333;
    auto in = test::looking(az, alt, t);
    in.right.squeeze = squeeze;
    ed.update(sync.sync(in), t);
    ASSERT_TRUE(ed.wait_for_visualizations(std::chrono::seconds(30)));
  };
  frame(0.0, 0.0, 0.0);
  const auto settings = ed.document().interpolation(EffectType::Exposure);
  const auto doc_keys = ed.document().keyframes(EffectType::Exposure);
  const cv::Mat before = ed.minimap_field().clone();
  ASSERT_LT(max_abs(before, expected_field(doc_keys, settings)), 1e-5);
  frame(0.0, 0.0, 1.0);  // grab: nothing moved yet, the field is the document's
  ASSERT_TRUE(ed.grabbing());
  const std::size_t held = *ed.selected_keyframe();
  ASSERT_EQ(held, doc_keys.size() - 1);
  EXPECT_LT(max_abs(ed.minimap_field(), before), 1e-7);
  for (int step = 1; step <= 3; ++step) {  // carry it 25 deg a frame to the right
    frame(25.0 * step, 0.0, 1.0);
    auto moved = doc_keys;
    moved[held].direction = ed.selected_preview()->direction;
    EXPECT_LT(max_abs(ed.minimap_field(), expected_field(moved, settings)), 1e-5)
        << "step " << step;
    EXPECT_GT(max_abs(ed.minimap_field(), before), 0.1)
        << "the field changed with the held keyframe";
    EXPECT_EQ(ed.document().keyframes(EffectType::Exposure), doc_keys)
        << "the document is untouched";
  }
  // Release commits the move; the field is the document's (now moved) solution.
  frame(75.0, 0.0, 0.0);
  ASSERT_FALSE(ed.grabbing());
  EXPECT_LT(max_abs(ed.minimap_field(),
                    expected_field(ed.document().keyframes(EffectType::Exposure), settings)),
            1e-5);
  // A grab cancelled by undo goes back to the document's field.
  frame(75.0, 0.0, 1.0);
  frame(100.0, 0.0, 1.0);
  ASSERT_TRUE(ed.grabbing());
  ed.undo();
  frame(100.0, 0.0, 1.0);
  EXPECT_LT(max_abs(ed.minimap_field(), before), 1e-5)
      << "undo restored the keyframe and the field";
}

INSTANTIATE_TEST_SUITE_P(Editor, GrabMinimap,
                         ::testing::Values(Case{"sync", false}, Case{"async", true}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vdfx::app
