/// @file
/// @brief An OpenXR-shaped session for the simulated headset: states, frame loop, views, spaces.
///
/// GL-free and clock-free: every call that needs the time takes it (ns), so tests and replays are
/// deterministic. Names follow OpenXR (xrWaitFrame/xrBeginFrame/xrEndFrame, XrSessionState,
/// XrFovf, reference spaces VIEW/LOCAL) so a real OpenXR backend can replace it later.
///
/// State machine (OpenXR 1.0, section "Session Lifecycle", simplified to one runtime):
///   IDLE --poll_event--> READY --begin()--> SYNCHRONIZED --first end_frame--> VISIBLE
///   --(input focus)--> FOCUSED; request_exit(): FOCUSED -> VISIBLE -> SYNCHRONIZED -> STOPPING
///   --end()--> IDLE --> EXITING. Every change is queued as an event for poll_event().
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "xr/headset/eye_views.h"
#include "xr/headset/hmd_profile.h"
#include "xr/headset/render_view.h"

namespace vdfx::xr {

enum class SessionState { Idle, Ready, Synchronized, Visible, Focused, Stopping, Exiting };
const char* to_string(SessionState s);

enum class ReferenceSpace { View, Local };

/// Poses (XrPosef) are xr/headset/pose.h's; a * b (Pose::operator*) is b's frame expressed in a's
/// parent.

/// XrFrameState.
struct FrameState {
  std::int64_t predicted_display_time_ns = 0;
  std::int64_t predicted_display_period_ns = 0;
  std::int64_t wait_ns = 0;  //!< how long a real runtime would have blocked in wait_frame
  bool should_render = false;
};

/// A UI panel: a textured quad in 3D, composited after the effects (they never touch it).
struct QuadLayer {
  ReferenceSpace space = ReferenceSpace::Local;
  Pose pose;                            //!< centre of the quad, +z towards the viewer
  Eigen::Vector2d size_m = {1.0, 0.5};  //!< width, height in metres
  /// GL texture name (0: none yet): premultiplied RGBA, its first row (as uploaded to GL) at
  /// the quad's top, as OpenXR's quad layers.
  unsigned texture = 0;
};

struct SessionStateEvent {
  SessionState state;
  std::int64_t time_ns;
};

class SessionError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

class Session {
 public:
  /// Refresh rate, IPD and eye FOVs come from the headset profile.
  explicit Session(HmdProfile profile);

  SessionState state() const { return state_; }
  /// Next queued state change (xrPollEvent). The runtime moves IDLE to READY on the first poll.
  std::optional<SessionStateEvent> poll_event(std::int64_t now_ns);
  /// xrBeginSession: READY -> SYNCHRONIZED; vsyncs are counted from `now_ns`.
  void begin(std::int64_t now_ns);
  /// xrRequestExitSession: walks the running states down to STOPPING.
  void request_exit(std::int64_t now_ns);
  /// xrEndSession: STOPPING -> IDLE -> EXITING.
  void end(std::int64_t now_ns);
  /// Input focus (the simulated "headset on"); FOCUSED <-> VISIBLE while running.
  void set_input_focus(bool focused, std::int64_t now_ns);

  /// xrWaitFrame: the vsync the frame about to be rendered will be shown at: the first vsync
  /// (begin time + k * period) strictly after both `now_ns` and the previous prediction.
  FrameState wait_frame(std::int64_t now_ns);
  /// xrBeginFrame: one per wait_frame.
  void begin_frame();
  /// xrEndFrame: `display_time_ns` must be the predicted time of the frame begun; stores the
  /// layers for the compositor.
  void end_frame(std::int64_t display_time_ns, std::vector<QuadLayer> quad_layers);
  const std::vector<QuadLayer>& submitted_quad_layers() const { return quads_; }

  /// xrLocateViews: both eyes at `head_in_local` (the input backend's pose at the display time),
  /// in VIEW (head-locked) or LOCAL space (xr/headset/eye_views.h does the per-eye geometry).
  std::array<EyeView, 2> locate_views(const Pose& head_in_local, ReferenceSpace space) const;
  /// The pose of a layer authored in `space`, in LOCAL.
  static Pose to_local(const Pose& pose, ReferenceSpace space, const Pose& head_in_local);
  const HmdProfile& profile() const { return profile_; }

 private:
  void set_state(SessionState s, std::int64_t now_ns);
  bool running() const;
  [[noreturn]] void fail(const std::string& call, const std::string& what) const;

  HmdProfile profile_;
  SessionState state_ = SessionState::Idle;
  std::deque<SessionStateEvent> events_;
  bool exit_requested_ = false;
  bool input_focus_ = true;
  std::int64_t period_ns_ = 0;
  std::int64_t epoch_ns_ = 0;
  std::int64_t last_predicted_ns_ = INT64_MIN;
  bool frame_waited_ = false, frame_begun_ = false;
  std::vector<QuadLayer> quads_;
};

/// The renderer's view of an eye located by the session (lens centre on the optical axis).
RenderView render_view(const EyeView& v);
/// Rotation and translation of a pose as Eigen types.
Eigen::Matrix3d rotation_of(const Pose& p);
Eigen::Vector3d position_of(const Pose& p);

}  // namespace vdfx::xr
