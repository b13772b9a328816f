/// @file
/// @brief The OpenXR input backend: xrSyncActions, the action states and the located aim and
/// head poses at the poll's time, turned into xr::InputState by xr/openxr/openxr_input.h.
#include "xr/input/input_backend.h"
#include "xr/openxr/gl/openxr_runtime_impl.h"
#include "xr/openxr/openxr_input.h"

namespace vdfx::xr {
namespace {

std::optional<Pose> located(XrSpace space, XrSpace base, XrTime t) {
  auto loc = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
  if (XR_FAILED(xrLocateSpace(space, base, t, &loc))) return std::nullopt;
  const XrSpaceLocationFlags need =
      XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT;
  if ((loc.locationFlags & need) != need) return std::nullopt;
  Pose p;
  p.position = {loc.pose.position.x, loc.pose.position.y, loc.pose.position.z};
  p.orientation = glm::dquat(loc.pose.orientation.w, loc.pose.orientation.x, loc.pose.orientation.y,
                             loc.pose.orientation.z);
  return p;
}

class OpenXrInput : public InputBackend {
 public:
  explicit OpenXrInput(OpenXrRuntime& runtime) : runtime_(runtime) {}

  std::string status() const override {
    const OpenXrRuntime::Impl& m = runtime_.impl();
    return "OpenXR " + m.info.runtime_name + ": " + session_state_name(m.lifecycle.state());
  }

 protected:
  InputState poll_state(std::int64_t t_ns) override {
    OpenXrInputSample s;
    s.t_ns = t_ns;
    OpenXrRuntime::Impl& m = runtime_.impl();
    // Before the first frame there is no display time to locate anything at.
    if (!m.session || !m.lifecycle.running() || !runtime_.has_epoch()) return openxr_input_state(s);
    XrActiveActionSet active{m.action_set, XR_NULL_PATH};
    auto si = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
    si.countActiveActionSets = 1;
    si.activeActionSets = &active;
    // XR_SESSION_NOT_FOCUSED (a success code) leaves every action inactive: nothing pressed.
    xr_check(xrSyncActions(m.session, &si), "xrSyncActions");
    const XrTime t = runtime_.to_xr_time(t_ns);
    s.head = located(m.view, m.local, t);
    for (int h = 0; h < 2; ++h) read_hand(m, h, t, h == 0 ? s.left : s.right);
    return openxr_input_state(s);
  }

 private:
  XrActionStateGetInfo get_info(const OpenXrRuntime::Impl& m, OpenXrAction a, int hand) const {
    auto gi = xr_struct<XrActionStateGetInfo>(XR_TYPE_ACTION_STATE_GET_INFO);
    gi.action = m.actions[static_cast<int>(a)];
    gi.subactionPath = m.hand_paths[hand];
    return gi;
  }
  double float_state(const OpenXrRuntime::Impl& m, OpenXrAction a, int hand) const {
    const XrActionStateGetInfo gi = get_info(m, a, hand);
    auto st = xr_struct<XrActionStateFloat>(XR_TYPE_ACTION_STATE_FLOAT);
    xr_check(xrGetActionStateFloat(m.session, &gi, &st), "xrGetActionStateFloat");
    return st.isActive ? st.currentState : 0.0;
  }
  bool bool_state(const OpenXrRuntime::Impl& m, OpenXrAction a, int hand) const {
    const XrActionStateGetInfo gi = get_info(m, a, hand);
    auto st = xr_struct<XrActionStateBoolean>(XR_TYPE_ACTION_STATE_BOOLEAN);
    xr_check(xrGetActionStateBoolean(m.session, &gi, &st), "xrGetActionStateBoolean");
    return st.isActive && st.currentState;
  }
  void read_hand(const OpenXrRuntime::Impl& m, int hand, XrTime t, OpenXrHandSample& out) const {
    const XrActionStateGetInfo pose_info = get_info(m, OpenXrAction::Aim, hand);
    auto pose = xr_struct<XrActionStatePose>(XR_TYPE_ACTION_STATE_POSE);
    xr_check(xrGetActionStatePose(m.session, &pose_info, &pose), "xrGetActionStatePose");
    if (pose.isActive) out.aim = located(m.aim[hand], m.local, t);
    out.trigger = float_state(m, OpenXrAction::Trigger, hand);
    out.squeeze = float_state(m, OpenXrAction::Squeeze, hand);
    const XrActionStateGetInfo stick_info = get_info(m, OpenXrAction::Thumbstick, hand);
    auto stick = xr_struct<XrActionStateVector2f>(XR_TYPE_ACTION_STATE_VECTOR2F);
    xr_check(xrGetActionStateVector2f(m.session, &stick_info, &stick), "xrGetActionStateVector2f");
    if (stick.isActive) out.thumbstick = {stick.currentState.x, stick.currentState.y};
    out.thumbstick_click = bool_state(m, OpenXrAction::ThumbstickClick, hand);
    out.primary = bool_state(m, OpenXrAction::Primary, hand);
    out.secondary = bool_state(m, OpenXrAction::Secondary, hand);
    out.menu = bool_state(m, OpenXrAction::Menu, hand);
  }

  OpenXrRuntime& runtime_;
};

}  // namespace

std::unique_ptr<InputBackend> create_openxr_input_backend(OpenXrRuntime& runtime) {
  return std::make_unique<OpenXrInput>(runtime);
}

}  // namespace vdfx::xr
