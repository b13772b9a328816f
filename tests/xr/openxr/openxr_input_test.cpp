/// @file
/// @brief OpenXR action values become the xr::InputState the other backends give: what a
/// recording of it stores and its replay returns, with the same edges.
#include "xr/openxr/openxr_input.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "xr/input/input_state_io.h"

namespace vdfx::xr {
namespace {

Pose pose(double az, double alt, glm::dvec3 p) {
  return {p, look_rotation(az, alt)};
}

OpenXrInputSample sample_with_hands() {
  OpenXrInputSample s;
  s.t_ns = 22'222'222;
  s.head = pose(30.0, 5.0, {0.0, 1.6, 0.0});
  s.right.aim = pose(20.0, -10.0, {0.2, 1.3, -0.3});
  s.right.trigger = 0.8;
  s.right.thumbstick = {0.25, -0.5};
  s.right.primary = true;
  s.left.aim = pose(-20.0, -10.0, {-0.2, 1.3, -0.3});
  s.left.squeeze = 1.0;
  s.left.menu = true;
  s.left.secondary = true;
  return s;
}

TEST(OpenXrInput, TrackedHandsCarryEveryValueAndGripIsAim) {
  const OpenXrInputSample s = sample_with_hands();
  const InputState in = openxr_input_state(s);
  EXPECT_EQ(in.t_ns, s.t_ns);
  EXPECT_TRUE(in.head_tracked);
  EXPECT_NEAR(forward_direction(in.head).azimuth_deg, 30.0, 1e-9);
  ASSERT_TRUE(in.right.tracked);
  EXPECT_EQ(in.right.grip, in.right.aim);
  EXPECT_DOUBLE_EQ(in.right.trigger, 0.8);
  EXPECT_DOUBLE_EQ(in.right.thumbstick.y, -0.5);
  EXPECT_TRUE(in.right.primary);
  EXPECT_TRUE(in.left.menu);
  EXPECT_TRUE(in.left.secondary);
  EXPECT_DOUBLE_EQ(in.left.squeeze, 1.0);
}

TEST(OpenXrInput, UntrackedHandIsTheDefaultStateWhateverItsButtonsSay) {
  OpenXrInputSample s = sample_with_hands();
  s.right.aim.reset();  // the controller lost tracking with the trigger pulled
  const InputState in = openxr_input_state(s);
  EXPECT_FALSE(in.right.tracked);
  EXPECT_EQ(in.right.trigger, 0.0);
  EXPECT_FALSE(in.right.primary);
  // What a recording stores for it (the hand omitted) replays to the same state.
  const InputState replayed = from_recorded_sample(to_recorded_sample(in));
  EXPECT_FALSE(replayed.right.tracked);
  EXPECT_EQ(replayed.right.trigger, in.right.trigger);
  EXPECT_EQ(replayed.right.aim, in.right.aim);
}

TEST(OpenXrInput, UntrackedHeadIsTheNeutralHead) {
  OpenXrInputSample s;
  s.t_ns = 5;
  const InputState in = openxr_input_state(s);
  EXPECT_FALSE(in.head_tracked);
  EXPECT_EQ(in.head, neutral_input_state(5).head);
  EXPECT_FALSE(in.left.tracked);
  EXPECT_FALSE(in.right.tracked);
}

TEST(OpenXrInput, OvershootIsClampedAndQuaternionsNormalised) {
  OpenXrInputSample s = sample_with_hands();
  s.right.trigger = 1.0000001;
  s.right.squeeze = -1e-7;
  s.right.thumbstick = {1.00001, -1.00001};
  s.right.aim->orientation *= 1.0001;  // a float quaternion's norm
  const InputState in = openxr_input_state(s);
  EXPECT_EQ(in.right.trigger, 1.0);
  EXPECT_EQ(in.right.squeeze, 0.0);
  EXPECT_EQ(in.right.thumbstick, glm::dvec2(1.0, -1.0));
  EXPECT_NEAR(glm::length(in.right.aim.orientation), 1.0, 1e-15);
}

TEST(OpenXrInput, RecordedAndReplayedStateIsTheSame) {
  const InputState in = openxr_input_state(sample_with_hands());
  const InputState replayed = from_recorded_sample(to_recorded_sample(in));
  EXPECT_EQ(replayed.head, in.head);
  EXPECT_EQ(replayed.right.aim, in.right.aim);
  EXPECT_EQ(replayed.right.trigger, in.right.trigger);
  EXPECT_EQ(replayed.right.thumbstick, in.right.thumbstick);
  EXPECT_EQ(replayed.left.menu, in.left.menu);
  EXPECT_EQ(replayed.left.squeeze, in.left.squeeze);
  // The edges a replay derives are the live ones.
  ActionSync live, replay;
  const InputState a = live.sync(in), b = replay.sync(replayed);
  EXPECT_EQ(a.edges.pressed, b.edges.pressed);
  EXPECT_TRUE(a.edges.was_pressed(Hand::Right, Control::Trigger));
  EXPECT_TRUE(a.edges.was_pressed(Hand::Left, Control::Menu));
}

TEST(OpenXrInput, RightMenuNeverReachesVdfxsLeftOnlyMenuPath) {
  OpenXrInputSample s = sample_with_hands();
  s.right.menu = true;
  EXPECT_FALSE(openxr_input_state(s).right.menu);
}

}  // namespace
}  // namespace vdfx::xr
