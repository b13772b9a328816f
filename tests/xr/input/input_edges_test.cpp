/// @file
/// @brief No lost input: the action edges (pressed / released since the previous poll) and the
/// sim's rule that a control changes at most once per poll, so a tap between two frames counts
/// exactly once, also through a recording and its replay.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/recording.h"
#include "tests/support/test_paths.h"
#include "xr/input/input_backend.h"

namespace vdfx::xr {
namespace {

constexpr std::int64_t kFrame = 33'333'333;

struct Counts {
  int pressed = 0, released = 0, polls_down = 0;
};

/// Polls `n` frames and counts the edges of one control.
Counts poll_frames(InputBackend& b, std::int64_t& t, int n, Hand h, Control c) {
  Counts k;
  for (int i = 0; i < n; ++i) {
    const InputState s = b.poll(t += kFrame);
    k.pressed += s.edges.was_pressed(h, c);
    k.released += s.edges.was_released(h, c);
    k.polls_down += s.edges.is_down(h, c);
  }
  return k;
}

TEST(InputEdges, KeyTapBetweenTwoFramesIsDownInExactlyOnePoll) {
  auto sim = create_sim_backend({});
  std::int64_t t = 0;
  sim->poll(t);
  sim->push_event(KeyEvent{Key::J, true});  // right a, pressed and released within one frame
  sim->push_event(KeyEvent{Key::J, false});
  const InputState first = sim->poll(t += kFrame);
  EXPECT_TRUE(first.right.primary);
  EXPECT_TRUE(first.edges.was_pressed(Hand::Right, Control::Primary));
  const InputState second = sim->poll(t += kFrame);
  EXPECT_FALSE(second.right.primary);
  EXPECT_TRUE(second.edges.was_released(Hand::Right, Control::Primary));
  const Counts rest = poll_frames(*sim, t, 5, Hand::Right, Control::Primary);
  EXPECT_EQ(rest.pressed + rest.released + rest.polls_down, 0);
}

TEST(InputEdges, DoubleTapWithinOneFrameCountsTwice) {
  auto sim = create_sim_backend({});
  std::int64_t t = 0;
  for (int i = 0; i < 2; ++i) {
    sim->push_event(KeyEvent{Key::X, true});  // left x: undo
    sim->push_event(KeyEvent{Key::X, false});
  }
  const Counts k = poll_frames(*sim, t, 8, Hand::Left, Control::Primary);
  EXPECT_EQ(k.pressed, 2);
  EXPECT_EQ(k.released, 2);
  EXPECT_EQ(k.polls_down, 2);
}

TEST(InputEdges, QuickClickIsOneTriggerPress) {
  auto sim = create_sim_backend({});
  std::int64_t t = 0;
  sim->push_event(MouseButtonEvent{MouseButton::Left, true});
  sim->push_event(MouseButtonEvent{MouseButton::Left, false});
  const InputState s = sim->poll(t += kFrame);
  EXPECT_EQ(s.right.trigger, 1.0);
  EXPECT_TRUE(s.edges.was_pressed(Hand::Right, Control::Trigger));
  const Counts rest = poll_frames(*sim, t, 3, Hand::Right, Control::Trigger);
  EXPECT_EQ(rest.pressed, 0);
  EXPECT_EQ(rest.released, 1);
}

TEST(InputEdges, EventsKeepTheirOrderAcrossTheDeferredRelease) {
  // The cursor moves while the button is tapped: the move before the release applies at once,
  // the one after it waits with the release, so the aim follows the events in order. (The left
  // button: Space aims at the view centre, not the cursor.)
  SimConfig cfg;
  auto sim = create_sim_backend(cfg);
  std::int64_t t = 0;
  sim->push_event(MouseMoveEvent{100.0, 100.0});
  sim->push_event(MouseButtonEvent{MouseButton::Left, true});
  sim->push_event(MouseMoveEvent{200.0, 300.0});
  sim->push_event(MouseButtonEvent{MouseButton::Left, false});
  sim->push_event(MouseMoveEvent{900.0, 500.0});
  const InputState a = sim->poll(t += kFrame);
  const InputState b = sim->poll(t += kFrame);
  EXPECT_EQ(a.right.trigger, 1.0);
  EXPECT_EQ(b.right.trigger, 0.0);
  // The aim of the first poll is the cursor at (200, 300): left of and above the centre.
  const glm::dvec3 fa = forward(a.right.aim), fb = forward(b.right.aim);
  EXPECT_LT(fa.x, 0.0);
  EXPECT_GT(fa.y, 0.0);
  EXPECT_GT(fb.x, 0.0);  // (900, 500): right of and below
  EXPECT_LT(fb.y, 0.0);
}

TEST(InputEdges, HeldKeysAndOtherControlsAreNotDelayed) {
  // Two different controls pressed within one frame both apply in that poll.
  auto sim = create_sim_backend({});
  std::int64_t t = 0;
  sim->push_event(KeyEvent{Key::G, true});
  sim->push_event(KeyEvent{Key::K, true});
  const InputState s = sim->poll(t += kFrame);
  EXPECT_TRUE(s.edges.was_pressed(Hand::Right, Control::Squeeze));
  EXPECT_TRUE(s.edges.was_pressed(Hand::Right, Control::Secondary));
}

TEST(InputEdges, AnalogControlsUseTheBindingThresholdsWithHysteresis) {
  ActionSync sync;
  InputState s = neutral_input_state(0);
  s.right.tracked = true;
  const auto step = [&](double trigger) {
    s.right.trigger = trigger;
    return sync.sync(s).edges;
  };
  EXPECT_FALSE(step(0.5).is_down(Hand::Right, Control::Trigger));  // between: stays up
  EXPECT_TRUE(step(0.6).was_pressed(Hand::Right, Control::Trigger));
  EXPECT_TRUE(step(0.5).is_down(Hand::Right, Control::Trigger));  // between: stays down
  EXPECT_TRUE(step(0.4).was_released(Hand::Right, Control::Trigger));
  s.right.thumbstick = {0.0, -0.9};
  EXPECT_TRUE(sync.sync(s).edges.was_pressed(Hand::Right, Control::StickDown));
  s.right.tracked = false;  // an untracked hand has nothing down
  EXPECT_TRUE(sync.sync(s).edges.was_released(Hand::Right, Control::StickDown));
}

TEST(InputEdges, RecordedTapReplaysAsATap) {
  const auto dir = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "xr";
  std::filesystem::create_directories(dir);
  const auto file = dir / "tap.vdrec.jsonl";
  {
    auto rec = create_recording_backend(create_sim_backend({}), file, {"sim", std::nullopt, "tap"});
    std::int64_t t = 0;
    rec->poll(t += kFrame);
    rec->push_event(KeyEvent{Key::J, true});
    rec->push_event(KeyEvent{Key::J, false});
    for (int i = 0; i < 4; ++i) rec->poll(t += kFrame);
  }
  auto replay = create_input_backend("replay:" + file.string());
  Counts k;
  for (const std::int64_t t : replay->timeline()) {
    const InputState s = replay->poll(t);
    k.pressed += s.edges.was_pressed(Hand::Right, Control::Primary);
    k.released += s.edges.was_released(Hand::Right, Control::Primary);
    k.polls_down += s.edges.is_down(Hand::Right, Control::Primary);
  }
  EXPECT_EQ(k.pressed, 1);
  EXPECT_EQ(k.released, 1);
  EXPECT_EQ(k.polls_down, 1);
}

}  // namespace
}  // namespace vdfx::xr
