/// @file
/// @brief Session: state machine, frame timing, views.
#include "xr/headset/session.h"

#include <climits>
#include <cmath>

namespace vdfx::xr {

const char* to_string(SessionState s) {
  switch (s) {
    case SessionState::Idle: return "IDLE";
    case SessionState::Ready: return "READY";
    case SessionState::Synchronized: return "SYNCHRONIZED";
    case SessionState::Visible: return "VISIBLE";
    case SessionState::Focused: return "FOCUSED";
    case SessionState::Stopping: return "STOPPING";
    case SessionState::Exiting: return "EXITING";
  }
  return "?";
}

Session::Session(HmdProfile profile) : profile_(std::move(profile)) {
  if (!(profile_.refresh_hz > 0.0 && profile_.refresh_hz <= 1000.0))
    throw SessionError("Session: refresh rate " + std::to_string(profile_.refresh_hz) +
                       " Hz of profile '" + profile_.name + "' is outside (0, 1000]");
  period_ns_ = static_cast<std::int64_t>(std::llround(1e9 / profile_.refresh_hz));
}

void Session::fail(const std::string& call, const std::string& what) const {
  throw SessionError("Session::" + call + ": " + what + " (state " + to_string(state_) + ")");
}

bool Session::running() const {
  return state_ == SessionState::Synchronized || state_ == SessionState::Visible ||
         state_ == SessionState::Focused || state_ == SessionState::Stopping;
}

void Session::set_state(SessionState s, std::int64_t now_ns) {
  if (s == state_) return;
  state_ = s;
  events_.push_back({s, now_ns});
}

std::optional<SessionStateEvent> Session::poll_event(std::int64_t now_ns) {
  if (events_.empty() && state_ == SessionState::Idle && !exit_requested_)
    set_state(SessionState::Ready, now_ns);
  if (events_.empty()) return std::nullopt;
  const SessionStateEvent e = events_.front();
  events_.pop_front();
  return e;
}

void Session::begin(std::int64_t now_ns) {
  if (state_ != SessionState::Ready) fail("begin", "the session is not READY");
  epoch_ns_ = now_ns;
  last_predicted_ns_ = INT64_MIN;
  set_state(SessionState::Synchronized, now_ns);
}

void Session::request_exit(std::int64_t now_ns) {
  if (!running()) fail("request_exit", "the session is not running");
  exit_requested_ = true;
  if (state_ == SessionState::Focused) set_state(SessionState::Visible, now_ns);
  if (state_ == SessionState::Visible) set_state(SessionState::Synchronized, now_ns);
  set_state(SessionState::Stopping, now_ns);
}

void Session::end(std::int64_t now_ns) {
  if (state_ != SessionState::Stopping) fail("end", "end() needs STOPPING (call request_exit)");
  set_state(SessionState::Idle, now_ns);
  if (exit_requested_) set_state(SessionState::Exiting, now_ns);
  frame_waited_ = frame_begun_ = false;
}

void Session::set_input_focus(bool focused, std::int64_t now_ns) {
  input_focus_ = focused;
  if (focused && state_ == SessionState::Visible) set_state(SessionState::Focused, now_ns);
  if (!focused && state_ == SessionState::Focused) set_state(SessionState::Visible, now_ns);
}

FrameState Session::wait_frame(std::int64_t now_ns) {
  if (!running()) fail("wait_frame", "the session is not running");
  if (frame_waited_) fail("wait_frame", "called twice without begin_frame");
  // First vsync strictly after now: floor division that is also right for now < epoch.
  const std::int64_t since = now_ns - epoch_ns_;
  std::int64_t k = since >= 0 ? since / period_ns_ + 1
                              : -((-since) / period_ns_) + ((-since) % period_ns_ ? 0 : 1);
  std::int64_t t = epoch_ns_ + k * period_ns_;
  if (t <= last_predicted_ns_) t = last_predicted_ns_ + period_ns_;
  FrameState f;
  f.predicted_display_time_ns = t;
  f.predicted_display_period_ns = period_ns_;
  // A real runtime returns one period before the display time it predicts.
  f.wait_ns = std::max<std::int64_t>(0, t - period_ns_ - now_ns);
  f.should_render = state_ == SessionState::Visible || state_ == SessionState::Focused;
  last_predicted_ns_ = t;
  frame_waited_ = true;
  return f;
}

void Session::begin_frame() {
  if (!frame_waited_) fail("begin_frame", "no wait_frame before it");
  if (frame_begun_) fail("begin_frame", "the previous frame was not ended");
  frame_waited_ = false;
  frame_begun_ = true;
}

void Session::end_frame(std::int64_t display_time_ns, std::vector<QuadLayer> quad_layers) {
  if (!frame_begun_) fail("end_frame", "no begin_frame since the last end_frame");
  if (display_time_ns != last_predicted_ns_)
    fail("end_frame", "display time " + std::to_string(display_time_ns) +
                          " ns is not the predicted " + std::to_string(last_predicted_ns_) + " ns");
  frame_begun_ = false;
  quads_ = std::move(quad_layers);
  if (state_ == SessionState::Synchronized && !exit_requested_) {
    set_state(SessionState::Visible, display_time_ns);
    if (input_focus_) set_state(SessionState::Focused, display_time_ns);
  }
}

std::array<EyeView, 2> Session::locate_views(const Pose& head_in_local,
                                             ReferenceSpace space) const {
  return locate_eye_views(space == ReferenceSpace::View ? Pose{} : head_in_local, profile_);
}

Pose Session::to_local(const Pose& pose, ReferenceSpace space, const Pose& head_in_local) {
  return space == ReferenceSpace::Local ? pose : head_in_local * pose;
}

Eigen::Matrix3d rotation_of(const Pose& p) {
  const glm::dquat& q = p.orientation;
  return Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
}

Eigen::Vector3d position_of(const Pose& p) {
  return {p.position.x, p.position.y, p.position.z};
}

RenderView render_view(const EyeView& v) {
  const double d = effects::kDegToRad;
  RenderView r =
      RenderView::from_angles(rotation_of(v.pose), v.fov.angle_left * d, v.fov.angle_right * d,
                              v.fov.angle_down * d, v.fov.angle_up * d);
  r.position = position_of(v.pose);
  return r;
}

}  // namespace vdfx::xr
