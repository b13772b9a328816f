/// @file
/// @brief Effect tracks, minimap, timeline markers and nearest/adjacent keyframes.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "app/editor/visualizations.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

TEST(EditorVisualizations, MinimapEqualsDirectInterpolationAtGridPoints) {
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, EditorOptions{});
  auto& doc = ed.document();
  doc.add_keyframe(EffectType::Exposure, {{30.0, 0.0}, 0, {2.0}});
  doc.add_keyframe(EffectType::Exposure, {{-100.0, 40.0}, 0, {-3.0}});
  doc.add_keyframe(EffectType::Exposure, {{170.0, -20.0}, 20, {1.0}});
  ed.update(test::looking(0.0, 0.0), 0);
  const cv::Mat& m = ed.minimap_field();
  ASSERT_EQ(m.cols, 128);
  ASSERT_EQ(m.rows, 64);
  const auto rbf = doc.keyframe_set(EffectType::Exposure).solution();
  for (const auto& [x, y] : {std::pair{0, 0}, {17, 31}, {64, 32}, {127, 63}, {90, 10}}) {
    const auto d = minimap_cell_direction(x, y, 128, 64);
    EXPECT_NEAR(m.at<float>(y, x), std::clamp(rbf->evaluate(d, 0)[0], -8.0, 8.0), 1e-5)
        << x << "," << y;
  }
  EXPECT_NEAR(minimap_cell_direction(64, 32, 128, 64).azimuth_deg, 180.0 / 128.0, 1e-9);
  // Recomputed on keyframe/frame/effect changes only, not every frame.
  const int n = ed.minimap_computations();
  ed.update(test::looking(10.0, 0.0), 1);
  EXPECT_EQ(ed.minimap_computations(), n);
  ed.seek(5);
  ed.update(test::looking(10.0, 0.0), 2);
  EXPECT_EQ(ed.minimap_computations(), n + 1);
}

TEST(EditorVisualizations, TrackSamplesTheInterpolantAtTheView) {
  Editor ed(test::empty_sidecar(60), DocumentOptions{{.async = false}}, EditorOptions{});
  ed.document().add_keyframe(EffectType::Contrast, {{0.0, 0.0}, 0, {0.5}});
  ed.document().add_keyframe(EffectType::Contrast, {{0.0, 0.0}, 59, {2.5}});
  ed.select_effect(EffectType::Contrast);
  ed.update(test::looking(0.0, 0.0), 0);
  const auto& v = ed.track_values();
  ASSERT_EQ(v.size(), 60u);
  EXPECT_NEAR(v.front(), 0.5, 1e-9);
  EXPECT_NEAR(v.back(), 2.5, 1e-9);
  const auto rbf = ed.document().keyframe_set(EffectType::Contrast).solution();
  EXPECT_NEAR(v[30], rbf->evaluate(effects::Direction{0.0, 0.0}, 30)[0], 1e-9);
  EXPECT_EQ(track_sample_frames(1000, 5), (std::vector<std::int64_t>{0, 250, 500, 749, 999}));
}

struct NearCase {
  double view_az, view_alt;
  std::vector<std::size_t> expected;
};

class MarkersNearView : public ::testing::TestWithParam<NearCase> {};

TEST_P(MarkersNearView, SelectsKeyframesWithinTheCone) {
  const std::vector<effects::Keyframe> ks = {{{0.0, 0.0}, 0, {1.0}},
                                             {{25.0, 0.0}, 10, {1.0}},
                                             {{35.0, 0.0}, 20, {1.0}},
                                             {{0.0, 80.0}, 30, {1.0}},
                                             {{180.0, 0.0}, 40, {1.0}}};
  const auto& c = GetParam();
  EXPECT_EQ(keyframes_near_view(ks, {c.view_az, c.view_alt}, 30.0), c.expected);
}

INSTANTIATE_TEST_SUITE_P(Cases, MarkersNearView,
                         ::testing::Values(NearCase{0.0, 0.0, {0, 1}},
                                           NearCase{30.0, 0.0, {0, 1, 2}}, NearCase{0.0, 60.0, {3}},
                                           NearCase{-170.0, 10.0, {4}},
                                           NearCase{-90.0, -45.0, {}}));

TEST(EditorVisualizations, EditorHighlightsMarkersNearTheView) {
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, EditorOptions{});
  ed.document().add_keyframe(EffectType::Exposure, {{0.0, 0.0}, 5, {1.0}});
  ed.document().add_keyframe(EffectType::Exposure, {{90.0, 0.0}, 50, {1.0}});
  ed.update(test::looking(80.0, 0.0), 0);
  EXPECT_EQ(ed.near_keyframes(), std::vector<std::size_t>{1});
  EXPECT_EQ(ed.ui().strip().keyframes(), (std::vector<int>{5, 50}));
  ed.update(test::looking(10.0, 0.0), 1);
  EXPECT_EQ(ed.near_keyframes(), std::vector<std::size_t>{0});
}

TEST(EditorVisualizations, NearestUsesSpaceAndTime) {
  const std::vector<effects::Keyframe> ks = {{{0.0, 0.0}, 0, {1.0}}, {{20.0, 0.0}, 30, {1.0}}};
  EXPECT_EQ(nearest_keyframe(ks, {15.0, 0.0}, 30, 1.0, 30.0), 1u);
  EXPECT_EQ(nearest_keyframe(ks, {15.0, 0.0}, 0, 1.0, 30.0), 0u);
  EXPECT_FALSE(nearest_keyframe({}, {0.0, 0.0}, 0, 1.0, 30.0).has_value());
  EXPECT_EQ(adjacent_keyframe(ks, {0.0, 0.0}, 0, +1), 1u);
  EXPECT_FALSE(adjacent_keyframe(ks, {0.0, 0.0}, 0, -1).has_value());
}

}  // namespace
}  // namespace vdfx::app
