/// @file
/// @brief Re-editing keyframes: the grab (right squeeze) selects the nearest keyframe, carries it
/// with the view and the playhead as a live preview, and commits one undoable move on release;
/// while selected, the effect widget shows and edits that keyframe's values; deselecting.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::Direction;
using effects::EffectType;
using test::looking;

constexpr std::int64_t kFrame = 33'333'333;

xr::InputState with(xr::InputState in, double squeeze, bool stick_click = false) {
  in.right.squeeze = squeeze;
  in.right.thumbstick_click = stick_click;
  return in;
}

/// An editor with two exposure keyframes: A (-30, 0) frame 10 +1 stop, B (40, 0) frame 10 -1.
class Grab : public ::testing::Test {
 protected:
  Grab() : ed_(test::empty_sidecar(90), DocumentOptions{{.async = false}}, EditorOptions{}) {
    ed_.document().add_keyframe(EffectType::Exposure, {{-30.0, 0.0}, 10, {1.0}});
    ed_.document().add_keyframe(EffectType::Exposure, {{40.0, 0.0}, 10, {-1.0}});
    ed_.seek(10);
    steps_before_ = ed_.document().undo_stack().undo_size();
  }
  void frame(double az, double alt, double squeeze, bool stick_click = false) {
    t_ += kFrame;
    ed_.update(sync_.sync(with(looking(az, alt, t_), squeeze, stick_click)), t_);
  }
  const effects::Keyframe& key(std::size_t i) {
    return ed_.document().keyframes(EffectType::Exposure).at(i);
  }
  std::size_t steps() { return ed_.document().undo_stack().undo_size() - steps_before_; }

  Editor ed_;
  xr::ActionSync sync_;  //!< the edges InputBackend::poll would add
  std::int64_t t_ = 0;
  std::size_t steps_before_ = 0;
};

TEST_F(Grab, SqueezeSelectsTheNearestKeyframeAndHighlightsIt) {
  frame(35.0, 0.0, 0.0);
  EXPECT_FALSE(ed_.selected_keyframe());
  EXPECT_EQ(ed_.ui().minimap().selected(), -1);
  frame(35.0, 0.0, 1.0);
  ASSERT_TRUE(ed_.selected_keyframe());
  EXPECT_EQ(*ed_.selected_keyframe(), 1u);  // B is nearest
  EXPECT_TRUE(ed_.grabbing());
  EXPECT_EQ(ed_.ui().minimap().selected(), 1);
  EXPECT_NE(ed_.status_text().find("GRAB keyframe 2/2"), std::string::npos) << ed_.status_text();
  // Released without turning: nothing moved, no undo step, still selected.
  frame(35.0, 0.0, 0.0);
  EXPECT_FALSE(ed_.grabbing());
  ASSERT_TRUE(ed_.selected_keyframe());
  EXPECT_EQ(steps(), 0u);
  EXPECT_EQ(key(1).direction.azimuth_deg, 40.0);
  EXPECT_NE(ed_.status_text().find("SELECTED keyframe 2/2"), std::string::npos)
      << ed_.status_text();
  EXPECT_NE(ed_.ui().title().text().find("keyframe 2 of 2"), std::string::npos)
      << ed_.ui().title().text();
  EXPECT_TRUE(ed_.ui().deselect_button().enabled());
}

TEST_F(Grab, NoKeyframeNoSelection) {
  ed_.select_effect(EffectType::Contrast);
  frame(0.0, 0.0, 1.0);
  EXPECT_FALSE(ed_.selected_keyframe());
  EXPECT_FALSE(ed_.grabbing());
  frame(0.0, 0.0, 0.0);
  EXPECT_EQ(steps(), 0u);
}

TEST_F(Grab, HeldKeyframeFollowsTheViewLiveAndReleaseIsOneUndoableMove) {
  frame(40.0, 0.0, 1.0);  // looking straight at B
  frame(50.0, 5.0, 1.0);
  frame(60.0, 10.0, 1.0);
  // Live: the document is untouched, the preview carries B to the view centre.
  EXPECT_EQ(key(1).direction.azimuth_deg, 40.0);
  EXPECT_EQ(steps(), 0u);
  const auto held = ed_.selected_preview();
  ASSERT_TRUE(held);
  EXPECT_NEAR(held->direction.azimuth_deg, 60.0, 1e-9);
  EXPECT_NEAR(held->direction.altitude_deg, 10.0, 1e-9);
  EXPECT_EQ(held->frame, 10);
  EXPECT_NEAR(ed_.current_params().exposure_stops, -1.0, 1e-9);  // B's value at the view centre
  // Elsewhere the preview interpolates with B where it is held.
  const effects::RbfInterpolator ref(std::vector<effects::Keyframe>{key(0), *held}, 1,
                                     ed_.document().interpolation(EffectType::Exposure), 30.0);
  for (const Direction d : {Direction{40.0, 0.0}, Direction{0.0, 30.0}})
    EXPECT_NEAR(ed_.params_for_view(d, 10).exposure_stops, ref.evaluate(d, 10)[0], 1e-9);
  // The minimap dot moves with it.
  EXPECT_NEAR(ed_.ui().minimap().keyframes().at(1).azimuth_deg, 60.0, 1e-9);
  EXPECT_NE(ed_.status_text().find("az 60 alt 10 frame 10"), std::string::npos)
      << ed_.status_text();

  frame(60.0, 10.0, 0.0);  // release
  EXPECT_EQ(steps(), 1u);
  EXPECT_EQ(ed_.document().undo_stack().next_undo_label(), "move keyframe");
  EXPECT_NEAR(key(1).direction.azimuth_deg, 60.0, 1e-9);
  EXPECT_NEAR(key(1).direction.altitude_deg, 10.0, 1e-9);
  EXPECT_EQ(key(1).params, std::vector<double>{-1.0});
  EXPECT_EQ(*ed_.selected_keyframe(), 1u);
  ASSERT_TRUE(ed_.undo());
  EXPECT_EQ(key(1).direction.azimuth_deg, 40.0);
  EXPECT_EQ(key(1).direction.altitude_deg, 0.0);
  ASSERT_TRUE(ed_.redo());
  EXPECT_NEAR(key(1).direction.azimuth_deg, 60.0, 1e-9);
}

TEST_F(Grab, KeyframeKeepsItsOffsetFromTheViewCentre) {
  frame(30.0, 0.0, 1.0);  // B is 10 deg right of the view
  frame(-170.0, 5.0, 1.0);
  frame(-170.0, 5.0, 0.0);
  EXPECT_NEAR(key(1).direction.azimuth_deg, -160.0, 1e-9);
  EXPECT_NEAR(key(1).direction.altitude_deg, 5.0, 1e-9);
}

TEST_F(Grab, HeldKeyframeFollowsThePlayheadToAnotherFrame) {
  frame(40.0, 0.0, 1.0);
  ed_.seek(25);  // scrubbing while holding retimes the keyframe by as many frames
  frame(40.0, 0.0, 1.0);
  EXPECT_EQ(ed_.selected_preview()->frame, 25);
  EXPECT_EQ(key(1).frame, 10);
  frame(40.0, 0.0, 0.0);
  EXPECT_EQ(key(1).frame, 25);
  EXPECT_EQ(key(1).direction.azimuth_deg, 40.0);
  EXPECT_EQ(steps(), 1u);
  ed_.undo();
  EXPECT_EQ(key(1).frame, 10);
}

TEST_F(Grab, MovingOntoAnotherKeyframeReplacesItAndUndoRestoresBoth) {
  frame(40.0, 0.0, 1.0);
  frame(-29.8, 0.0, 1.0);  // within 0.5 deg of A at the same frame
  // The preview already drops A: at A's place the value is B's.
  EXPECT_NEAR(ed_.params_for_view({-30.0, 0.0}, 10).exposure_stops, -1.0, 1e-2);
  frame(-29.8, 0.0, 0.0);
  ASSERT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 1u);
  EXPECT_NEAR(key(0).direction.azimuth_deg, -29.8, 1e-9);
  EXPECT_EQ(key(0).params, std::vector<double>{-1.0});  // the moved keyframe wins
  EXPECT_EQ(*ed_.selected_keyframe(), 0u);              // and stays selected at its new index
  EXPECT_EQ(steps(), 1u);
  ASSERT_TRUE(ed_.undo());
  ASSERT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 2u);
  EXPECT_EQ(key(0).direction.azimuth_deg, -30.0);
  EXPECT_EQ(key(0).params, std::vector<double>{1.0});
  EXPECT_EQ(key(1).direction.azimuth_deg, 40.0);
  // The undo renumbered the keyframes: index 0 is now A, not the moved one, so no selection.
  EXPECT_FALSE(ed_.selected_keyframe());
}

TEST_F(Grab, SelectedKeyframeParamsAreEditedInsteadOfTheChosenValues) {
  frame(40.0, 0.0, 1.0);
  frame(40.0, 0.0, 0.0);
  // The slider keeps a position in [0, 1] and maps it back to the range: equal to a few ulps
  // (fused multiply-adds with -march=x86-64-v3 round differently).
  auto* slider = dynamic_cast<const ui::Slider1D*>(&ed_.ui().effect_widget(EffectType::Exposure));
  EXPECT_NEAR(slider->get(), -1.0, 1e-12);  // the widget shows the keyframe's value
  ed_.set_selected_params({2.5});
  EXPECT_EQ(key(1).params, std::vector<double>{2.5});
  EXPECT_EQ(ed_.document().params(EffectType::Exposure),
            std::vector<double>{0.0});  // chosen untouched
  EXPECT_EQ(steps(), 1u);
  EXPECT_EQ(ed_.document().undo_stack().next_undo_label(), "keyframe parameters");
  frame(40.0, 0.0, 0.0);
  EXPECT_NEAR(slider->get(), 2.5, 1e-12);
  ed_.undo();
  EXPECT_EQ(key(1).params, std::vector<double>{-1.0});
  EXPECT_EQ(ed_.selected_keyframe(), std::optional<std::size_t>(1));  // same keyframes: kept
  frame(40.0, 0.0, 0.0);
  EXPECT_NEAR(slider->get(), -1.0, 1e-12);
  ed_.redo();
  EXPECT_EQ(key(1).params, std::vector<double>{2.5});
  // Deselecting (right thumbstick click) returns the widget to the chosen values.
  frame(40.0, 0.0, 0.0, true);
  EXPECT_FALSE(ed_.selected_keyframe());
  EXPECT_NEAR(slider->get(), 0.0, 1e-12);
  ed_.set_selected_params({3.0});  // no selection: nothing to edit
  EXPECT_EQ(key(1).params, std::vector<double>{2.5});
}

TEST_F(Grab, DeleteRemovesTheSelectedKeyframeNotTheNearest) {
  frame(-30.0, 0.0, 1.0);  // select A
  frame(-30.0, 0.0, 0.0);
  frame(40.0, 0.0, 0.0);  // look at B
  ASSERT_TRUE(ed_.delete_nearest());
  ASSERT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 1u);
  EXPECT_EQ(key(0).direction.azimuth_deg, 40.0);
  EXPECT_FALSE(ed_.selected_keyframe());
}

TEST_F(Grab, TriggerOnNothingDeselectsAndPreviewsANewKeyframe) {
  frame(40.0, 0.0, 1.0);
  frame(40.0, 0.0, 0.0);
  ASSERT_TRUE(ed_.selected_keyframe());
  auto in = looking(0.0, 0.0, t_ += kFrame);
  in.right.trigger = 1.0;
  ed_.update(sync_.sync(in), t_);
  EXPECT_FALSE(ed_.selected_keyframe());
  EXPECT_TRUE(ed_.previewing());
}

TEST_F(Grab, UndoWhileHoldingCancelsTheGrab) {
  ed_.set_chosen_params({3.0});  // an edit to undo
  const auto before = steps();
  frame(40.0, 0.0, 1.0);
  frame(70.0, 0.0, 1.0);
  ed_.undo();
  EXPECT_FALSE(ed_.grabbing());
  frame(70.0, 0.0, 0.0);  // releasing after the cancel moves nothing
  EXPECT_EQ(key(1).direction.azimuth_deg, 40.0);
  EXPECT_EQ(steps(), before - 1);
}

TEST_F(Grab, SwitchingEffectOrDeletingFromOutsideDropsTheSelection) {
  frame(40.0, 0.0, 1.0);
  frame(40.0, 0.0, 0.0);
  ed_.select_effect(EffectType::Tint);
  EXPECT_FALSE(ed_.selected_keyframe());
  ed_.select_effect(EffectType::Exposure);
  frame(40.0, 0.0, 1.0);
  frame(40.0, 0.0, 0.0);
  ed_.document().remove_keyframe(EffectType::Exposure, 1);
  frame(40.0, 0.0, 0.0);
  EXPECT_FALSE(ed_.selected_keyframe());
}

// The same through the sim and the panels: G grabs, a slider drag on the selected keyframe is
// one undo step, the Deselect button leaves the selection.
TEST(GrabPanels, SliderDragOnTheSelectedKeyframeIsOneUndoStep) {
  EditorOptions o;
  o.layout = PanelLayout::Desktop;
  auto sim = xr::create_sim_backend({});
  Editor ed(test::empty_sidecar(test::kClipFrames), DocumentOptions{{.async = false}}, o);
  ed.document().add_keyframe(EffectType::Exposure, {{0.0, 0.0}, 0, {1.0}});
  std::int64_t t = 0;
  auto step = [&](int n = 1) {
    for (int i = 0; i < n; ++i, t += test::kFrameNs) ed.update(sim->poll(t), t);
  };
  auto key = [&](xr::Key k) {
    sim->push_event(xr::KeyEvent{k, true});
    step(2);
    sim->push_event(xr::KeyEvent{k, false});
    step(2);
  };
  auto mouse = [&](glm::dvec2 p, std::optional<bool> down = std::nullopt) {
    sim->push_event(xr::MouseMoveEvent{p.x, p.y});
    if (down) sim->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, *down});
    step(2);
  };
  step();
  key(xr::Key::G);
  ASSERT_TRUE(ed.selected_keyframe());
  const auto steps0 = ed.document().undo_stack().undo_size();
  auto* s = dynamic_cast<const ui::Slider1D*>(&ed.ui().effect_widget(EffectType::Exposure));
  const double y = s->rect().y + s->rect().h / 2;
  auto px = [&](double v) {
    return test::cursor_for(kEffectPanelId,
                            {s->track_x0() + (v + 8.0) / 16.0 * (s->track_x1() - s->track_x0()), y},
                            test::kClipFrames);
  };
  mouse(px(1.0), true);
  for (double v : {1.5, 2.0, 3.0}) mouse(px(v));
  mouse(px(3.0), false);
  EXPECT_NEAR(ed.document().keyframes(EffectType::Exposure)[0].params[0], 3.0, 1e-9);
  EXPECT_EQ(ed.document().params(EffectType::Exposure)[0], 0.0);
  EXPECT_EQ(ed.document().undo_stack().undo_size(), steps0 + 1);
  const glm::dvec2 deselect = test::widget_cursor(kEffectPanelId, "deselect", test::kClipFrames);
  mouse(deselect, true);
  mouse(deselect, false);
  EXPECT_FALSE(ed.selected_keyframe());
  EXPECT_NEAR(s->get(), 0.0, 1e-12);  // to a few ulps (slider position mapped back)
}

}  // namespace
}  // namespace vdfx::app
