/// @file
/// @brief The OpenXR session lifecycle as vdfx drives it (OpenXR 1.0, "Session Lifecycle"):
/// which call each state change asks for, and when the program leaves.
///
///   READY         -> xrBeginSession; frames run (SYNCHRONIZED, VISIBLE, FOCUSED)
///   STOPPING      -> xrEndSession; back to IDLE, where the runtime may make it READY again
///   EXITING       -> leave: the runtime wants the application to quit (or vdfx asked to)
///   LOSS_PENDING  -> leave: the session is being lost (a headset unplugged); the runtime may
///                    offer a new one later, vdfx simply ends with its document saved
/// vdfx asks to leave (window closed, Escape, --frames reached, the client done) with
/// xrRequestExitSession while the session runs, then follows the states to EXITING; before it
/// ever ran, it leaves at once.
///
/// Pure (no loader call): xr/openxr/gl/openxr_session.cpp makes the calls; tests step it by hand.
#pragma once

#include <openxr/openxr.h>

#include <string>

namespace vdfx::xr {

/// What the backend must do after a state change.
enum class LifecycleStep {
  Nothing,
  BeginSession,  //!< xrBeginSession (READY)
  EndSession,    //!< xrEndSession (STOPPING)
  Leave,         //!< destroy the session and end the loop (EXITING, LOSS_PENDING)
};

class OpenXrLifecycle {
 public:
  /// An XrEventDataSessionStateChanged's new state.
  LifecycleStep on_state(XrSessionState state);
  /// XrEventDataInstanceLossPending: the runtime is going away.
  LifecycleStep on_instance_loss();
  /// A call answered XR_ERROR_SESSION_LOST (the loss came before its event).
  LifecycleStep on_session_lost();
  /// vdfx wants to leave: true when xrRequestExitSession must be called now (the session runs
  /// and has not been asked yet); when it never ran, leaving() becomes true at once.
  bool request_exit();

  XrSessionState state() const { return state_; }
  /// Between xrBeginSession and xrEndSession: frames must be waited, begun and ended.
  bool running() const { return running_; }
  /// The loop should end (after destroying the session).
  bool leaving() const { return leaving_; }
  bool exit_requested() const { return exit_requested_; }
  /// Why the loop ends, for the user ("the runtime ended the session (EXITING)"); empty while
  /// running and when vdfx itself asked to leave.
  const std::string& reason() const { return reason_; }
  /// The session was lost (LOSS_PENDING or instance loss), not ended in order.
  bool lost() const { return lost_; }

 private:
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  bool running_ = false;
  bool leaving_ = false;
  bool exit_requested_ = false;
  bool lost_ = false;
  std::string reason_;
};

/// "XR_SESSION_STATE_FOCUSED" without the prefix: "FOCUSED".
const char* session_state_name(XrSessionState state);

}  // namespace vdfx::xr
