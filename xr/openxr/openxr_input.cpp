/// @file
/// @brief OpenXR action values -> xr::InputState.
#include "xr/openxr/openxr_input.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

namespace vdfx::xr {
namespace {

Pose normalised(const Pose& p) {
  return {p.position, glm::normalize(p.orientation)};
}

HandState hand_state(const OpenXrHandSample& s) {
  HandState h;
  if (!s.aim) return h;  // untracked: nothing down, as a recording without the hand replays
  h.tracked = true;
  h.aim = normalised(*s.aim);
  h.grip = h.aim;
  h.trigger = std::clamp(s.trigger, 0.0, 1.0);
  h.squeeze = std::clamp(s.squeeze, 0.0, 1.0);
  h.thumbstick = {std::clamp(s.thumbstick.x, -1.0, 1.0), std::clamp(s.thumbstick.y, -1.0, 1.0)};
  h.thumbstick_click = s.thumbstick_click;
  h.primary = s.primary;
  h.secondary = s.secondary;
  h.menu = s.menu;
  return h;
}

}  // namespace

InputState openxr_input_state(const OpenXrInputSample& sample) {
  InputState s;
  s.t_ns = sample.t_ns;
  if (sample.head) {
    s.head_tracked = true;
    s.head = normalised(*sample.head);
  } else {
    s.head = neutral_input_state(sample.t_ns).head;
  }
  s.left = hand_state(sample.left);
  s.right = hand_state(sample.right);
  // vdfx's menu path is the left hand's only (docs/input.md); a right menu never reaches it.
  s.right.menu = false;
  return s;
}

}  // namespace vdfx::xr
