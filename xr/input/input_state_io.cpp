/// @file
/// @brief Conversions between actions and recorded samples.
#include "xr/input/input_state_io.h"

namespace vdfx::xr {

namespace {

io::RecordedPose to_recorded(const Pose& p) {
  return {{p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z},
          {p.position.x, p.position.y, p.position.z}};
}

Pose from_recorded(const io::RecordedPose& r) {
  Pose p;
  p.orientation =
      glm::dquat(r.q[0], r.q[1], r.q[2], r.q[3]);  // glm's constructor takes (w, x, y, z)
  p.position = {r.p[0], r.p[1], r.p[2]};
  return p;
}

io::RecordedHand to_recorded(const HandState& h, bool left) {
  io::RecordedHand r;
  r.aim = to_recorded(h.aim);
  r.trigger = h.trigger;
  r.squeeze = h.squeeze;
  r.stick = {h.thumbstick.x, h.thumbstick.y};
  r.primary = h.primary;
  r.secondary = h.secondary;
  r.menu = left && h.menu;
  r.stick_click = h.thumbstick_click;
  return r;
}

HandState from_recorded(const io::RecordedHand& r) {
  HandState h;
  h.tracked = true;
  h.aim = from_recorded(r.aim);
  h.grip = h.aim;
  h.trigger = r.trigger;
  h.squeeze = r.squeeze;
  h.thumbstick = {r.stick[0], r.stick[1]};
  h.primary = r.primary;
  h.secondary = r.secondary;
  h.menu = r.menu;
  h.thumbstick_click = r.stick_click;
  return h;
}

}  // namespace

io::RecordedSample to_recorded_sample(const InputState& s) {
  io::RecordedSample r;
  r.t_ns = s.t_ns;
  r.head = to_recorded(s.head);
  if (s.left.tracked) r.left = to_recorded(s.left, true);
  if (s.right.tracked) r.right = to_recorded(s.right, false);
  return r;
}

InputState from_recorded_sample(const io::RecordedSample& r) {
  InputState s;
  s.t_ns = r.t_ns;
  s.head_tracked = true;
  s.head = from_recorded(r.head);
  if (r.left) s.left = from_recorded(*r.left);
  if (r.right) s.right = from_recorded(*r.right);
  return s;
}

}  // namespace vdfx::xr
