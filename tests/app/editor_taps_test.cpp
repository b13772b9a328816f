/// @file
/// @brief No lost taps in the editor: keys and clicks pressed and released between two frames
/// (the sim's events queued before one poll, as a slow frame sees a quick tap) act exactly once.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

EditorOptions desktop() {
  EditorOptions o;
  o.layout = PanelLayout::Desktop;
  return o;
}

class Taps : public ::testing::Test {
 protected:
  Taps()
      : sim_(xr::create_sim_backend({})),
        ed_(test::empty_sidecar(90), DocumentOptions{{.async = false}}, desktop()) {
    step();
  }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i, t_ += test::kFrameNs) ed_.update(sim_->poll(t_), t_);
  }
  /// A key pressed and released between two frames.
  void tap(xr::Key k) {
    sim_->push_event(xr::KeyEvent{k, true});
    sim_->push_event(xr::KeyEvent{k, false});
    step(3);
  }
  /// The cursor moved to a pixel and clicked there between two frames.
  void click(glm::dvec2 cursor) {
    sim_->push_event(xr::MouseMoveEvent{cursor.x, cursor.y});
    sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
    sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
    step(3);
  }
  std::size_t count() { return ed_.document().keyframes(EffectType::Exposure).size(); }

  std::unique_ptr<xr::InputBackend> sim_;
  Editor ed_;
  std::int64_t t_ = 0;
};

TEST_F(Taps, SpaceTapPlacesOneKeyframe) {
  tap(xr::Key::Space);
  EXPECT_EQ(count(), 1u) << ed_.status_text();
  EXPECT_EQ(ed_.document().undo_stack().undo_size(), 1u);
  ed_.set_chosen_params({2.0});
  tap(xr::Key::Space);  // the same place and frame: replaces it, still one keyframe
  ASSERT_EQ(count(), 1u);
  EXPECT_EQ(ed_.document().keyframes(EffectType::Exposure)[0].params[0], 2.0);
}

TEST_F(Taps, ClickOnTheVideoPlacesOneKeyframe) {
  click({640.0, 300.0});  // the centre area of the view holds no panel
  EXPECT_EQ(count(), 1u) << ed_.status_text();
}

TEST_F(Taps, KeyTapsDeleteUndoAndRedoOnce) {
  for (double az : {-20.0, 0.0, 20.0})
    ed_.document().add_keyframe(EffectType::Exposure, {{az, 0.0}, 0, {1.0}});
  tap(xr::Key::J);  // right a: deletes the nearest, once
  EXPECT_EQ(count(), 2u);
  tap(xr::Key::X);  // left x: undo
  EXPECT_EQ(count(), 3u);
  tap(xr::Key::Y);  // left y: redo
  EXPECT_EQ(count(), 2u);
  // A double tap within one frame is two deletes.
  for (int i = 0; i < 2; ++i) {
    sim_->push_event(xr::KeyEvent{xr::Key::J, true});
    sim_->push_event(xr::KeyEvent{xr::Key::J, false});
  }
  step(6);
  EXPECT_EQ(count(), 0u);
}

TEST_F(Taps, QuickClickOnAButtonClicksIt) {
  ed_.document().add_keyframe(EffectType::Exposure, {{0.0, 0.0}, 0, {1.0}});
  step();
  ASSERT_EQ(count(), 1u);
  const ui::Rect r = ed_.ui().undo_button().rect();
  click(test::cursor_for(kEffectPanelId, r.centre()));
  EXPECT_EQ(count(), 0u) << ed_.status_text();
  EXPECT_EQ(ed_.document().undo_stack().redo_size(), 1u);
}

}  // namespace
}  // namespace vdfx::app
