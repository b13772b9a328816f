/// @file
/// @brief The editor's timeline panel while playing: each video frame re-renders only what the
/// frame changed (playhead columns, labels), and the result is pixel-identical to a full redraw.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "app/editor/editor.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

struct PlaybackCase {
  const char* name;
  EffectType current;  //!< the effect shown (its keyframes make the minimap change per frame)
  bool partial_only;   //!< every playback render must be partial
};

const PlaybackCase kCases[] = {
    {"EffectWithoutKeyframes", EffectType::Contrast, true},
    {"EffectWithKeyframesOverTime", EffectType::Exposure, false},
};

class PlaybackRender : public ::testing::TestWithParam<PlaybackCase> {};

TEST_P(PlaybackRender, PartialRendersEqualAFullRedraw) {
  Editor ed(test::empty_sidecar(240), DocumentOptions{{.async = false}}, EditorOptions{});
  ed.document().add_keyframe(EffectType::Exposure, {{30.0, 0.0}, 3, {1.5}});
  ed.document().add_keyframe(EffectType::Exposure, {{-60.0, 10.0}, 7, {-2.0}});
  ed.select_effect(GetParam().current);
  std::int64_t t = 0;
  ed.update(test::looking(10.0, 0.0, t), t);
  ui::Panel& p = *ed.panel(kTimelinePanelId);
  p.texture();
  const int full0 = p.full_render_count();
  ed.set_playing(true);
  for (int i = 0; i < 12; ++i) {  // crosses both keyframe frames
    t += 33'333'334;
    ed.update(test::looking(10.0, 0.0, t), t);
    ASSERT_TRUE(p.dirty()) << i;
    EXPECT_TRUE(p.render_if_dirty());
  }
  EXPECT_EQ(ed.frame(), 12);
  if (GetParam().partial_only) {
    EXPECT_EQ(p.full_render_count(), full0) << "playback should render partially";
  }
  const cv::Mat partial = p.texture().clone();
  const int before = p.full_render_count();
  p.mark_dirty();
  const cv::Mat& full = p.texture();
  EXPECT_EQ(p.full_render_count(), before + 1);
  EXPECT_EQ(cv::norm(partial, full, cv::NORM_INF), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Editor, PlaybackRender, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vdfx::app
