/// @file
/// @brief The authoring tools: trigger preview at the view centre, place on release, replace,
/// delete nearest, unaltered (B), undo/redo bindings, playback frames.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using test::looking;

constexpr std::int64_t kFrame = 33'333'333;

Editor make_editor(std::int64_t frames = 90) {
  return Editor(test::empty_sidecar(frames), DocumentOptions{{.async = false}}, EditorOptions{});
}

/// The right trigger at `v` (run it through an xr::ActionSync for its edges, as a backend's poll).
xr::InputState with_trigger(xr::InputState in, double v) {
  in.right.trigger = v;
  return in;
}

TEST(EditorTools, TriggerPreviewsFollowsHeadAndPlacesOnRelease) {
  Editor ed = make_editor();
  xr::ActionSync sync;  //!< the edges InputBackend::poll would add
  ed.set_chosen_params({2.0});
  std::int64_t t = 0;
  ed.update(looking(10.0, 0.0, t), t);
  EXPECT_FALSE(ed.previewing());
  EXPECT_EQ(ed.current_params().exposure_stops, 0.0);
  t += kFrame;
  ed.update(sync.sync(with_trigger(looking(10.0, 0.0, t), 1.0)), t);
  EXPECT_TRUE(ed.previewing());
  EXPECT_EQ(ed.current_params().exposure_stops, 2.0);  // as if a keyframe sat at the view centre
  EXPECT_TRUE(ed.document().keyframes(EffectType::Exposure).empty());
  // Turning the head moves the preview with it; nothing is placed yet.
  t += kFrame;
  ed.update(sync.sync(with_trigger(looking(40.0, 5.0, t), 1.0)), t);
  EXPECT_EQ(ed.current_params().exposure_stops, 2.0);
  t += kFrame;
  ed.update(sync.sync(with_trigger(looking(40.0, 5.0, t), 0.0)), t);
  EXPECT_FALSE(ed.previewing());
  const auto& ks = ed.document().keyframes(EffectType::Exposure);
  ASSERT_EQ(ks.size(), 1u);
  EXPECT_NEAR(ks[0].direction.azimuth_deg, 40.0, 1e-9);
  EXPECT_NEAR(ks[0].direction.altitude_deg, 5.0, 1e-9);
  EXPECT_EQ(ks[0].frame, 0);
  EXPECT_EQ(ks[0].params, std::vector<double>{2.0});
}

TEST(EditorTools, PreviewAwayFromTheViewInterpolatesWithThePreviewKeyframe) {
  Editor ed = make_editor();
  xr::ActionSync sync;  //!< the edges InputBackend::poll would add
  ed.document().add_keyframe(EffectType::Exposure, {{-90.0, 0.0}, 0, {-2.0}});
  ed.set_chosen_params({3.0});
  ed.update(sync.sync(with_trigger(looking(60.0, 0.0), 1.0)), 0);
  ASSERT_TRUE(ed.previewing());
  const effects::RbfInterpolator ref(
      std::vector<effects::Keyframe>{{{-90.0, 0.0}, 0, {-2.0}}, {{60.0, 0.0}, 0, {3.0}}}, 1,
      ed.document().interpolation(EffectType::Exposure), 30.0);
  for (const effects::Direction d : {effects::Direction{0.0, 0.0}, effects::Direction{150.0, 30.0}})
    EXPECT_NEAR(ed.params_for_view(d, 0).exposure_stops,
                std::clamp(ref.evaluate(d, 0)[0], -8.0, 8.0), 1e-9);
}

TEST(EditorTools, ReleaseNearAnExistingKeyframeOnTheSameFrameReplacesIt) {
  Editor ed = make_editor();
  xr::ActionSync sync;  //!< the edges InputBackend::poll would add
  ed.set_chosen_params({1.0});
  std::int64_t t = 0;
  auto click_at = [&](double az) {
    t += kFrame;
    ed.update(sync.sync(with_trigger(looking(az, 0.0, t), 1.0)), t);
    t += kFrame;
    ed.update(sync.sync(with_trigger(looking(az, 0.0, t), 0.0)), t);
  };
  click_at(20.0);
  ed.set_chosen_params({-1.0});
  click_at(20.3);
  ASSERT_EQ(ed.document().keyframes(EffectType::Exposure).size(), 1u);
  EXPECT_EQ(ed.document().keyframes(EffectType::Exposure)[0].params, std::vector<double>{-1.0});
  click_at(25.0);
  EXPECT_EQ(ed.document().keyframes(EffectType::Exposure).size(), 2u);
}

TEST(EditorTools, ButtonADeletesTheKeyframeNearestTheView) {
  Editor ed = make_editor();
  for (double az : {-60.0, 0.0, 70.0})
    ed.document().add_keyframe(EffectType::Exposure, {{az, 0.0}, 0, {az / 30.0}});
  auto in = looking(55.0, 0.0);
  in.right.primary = true;
  xr::ActionSync sync;
  ed.update(sync.sync(in), 0);
  ed.update(sync.sync(in), kFrame);  // held: deletes once
  const auto& ks = ed.document().keyframes(EffectType::Exposure);
  ASSERT_EQ(ks.size(), 2u);
  for (const auto& k : ks) EXPECT_NE(k.direction.azimuth_deg, 70.0);
}

TEST(EditorTools, HoldingBShowsTheUnalteredFilm) {
  Editor ed = make_editor();
  ed.document().add_keyframe(EffectType::Saturation, {{0.0, 0.0}, 0, {2.0}});
  auto in = looking(0.0, 0.0);
  xr::ActionSync sync;
  ed.update(sync.sync(in), 0);
  EXPECT_EQ(ed.current_params().saturation, 2.0);
  in.right.secondary = true;
  ed.update(sync.sync(in), kFrame);
  EXPECT_TRUE(ed.unaltered());
  const effects::StackParams neutral;
  EXPECT_EQ(ed.current_params().saturation, neutral.saturation);
  in.right.secondary = false;
  ed.update(sync.sync(in), 2 * kFrame);
  EXPECT_EQ(ed.current_params().saturation, 2.0);
}

TEST(EditorTools, LeftXUndoesAndLeftYRedoes) {
  Editor ed = make_editor();
  ed.document().add_keyframe(EffectType::Exposure, {{0.0, 0.0}, 0, {1.0}});
  auto in = looking(0.0, 0.0);
  in.left.tracked = true;
  in.left.aim.orientation = xr::look_rotation(180.0, 0.0);  // away from every panel
  in.left.primary = true;
  xr::ActionSync sync;
  ed.update(sync.sync(in), 0);
  EXPECT_TRUE(ed.document().keyframes(EffectType::Exposure).empty());
  in.left.primary = false;
  in.left.secondary = true;
  ed.update(sync.sync(in), kFrame);
  EXPECT_EQ(ed.document().keyframes(EffectType::Exposure).size(), 1u);
}

TEST(EditorTools, PlaybackAdvancesFramesFromTheDisplayTimeAndWraps) {
  Editor ed = make_editor(30);
  ed.update(looking(0.0, 0.0), 0);
  ed.seek(10);
  ed.set_playing(true);
  const auto at = [](std::int64_t f) {
    return io::frame_start_ns(f, {30, 1});
  };  // exact frame starts
  ed.update(looking(0.0, 0.0), at(10));
  EXPECT_EQ(ed.frame(), 20);
  ed.update(looking(0.0, 0.0), at(25));
  EXPECT_EQ(ed.frame(), 5);  // 35 wraps to 5
  ed.set_playing(false);
  ed.update(looking(0.0, 0.0), at(40));
  EXPECT_EQ(ed.frame(), 5);
}

TEST(EditorTools, JumpToKeyframeSeeksAndSaysWhereToLook) {
  Editor ed = make_editor();
  ed.document().add_keyframe(EffectType::Exposure, {{100.0, 10.0}, 30, {1.0}});
  ed.document().add_keyframe(EffectType::Exposure, {{-20.0, 0.0}, 60, {1.0}});
  ed.update(looking(0.0, 0.0), 0);
  const auto d = ed.jump_to_keyframe(+1);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(ed.frame(), 30);
  EXPECT_EQ(d->azimuth_deg, 100.0);
  EXPECT_NE(ed.status_text().find("look 100 deg right, 10 deg up"), std::string::npos)
      << ed.status_text();
  EXPECT_TRUE(ed.jump_to_keyframe(+1));
  EXPECT_EQ(ed.frame(), 60);
  EXPECT_FALSE(ed.jump_to_keyframe(+1));
  EXPECT_TRUE(ed.jump_to_keyframe(-1));
  EXPECT_EQ(ed.frame(), 30);
}

}  // namespace
}  // namespace vdfx::app
