/// @file
/// @brief The session lifecycle's steps.
#include "xr/openxr/openxr_lifecycle.h"

namespace vdfx::xr {

LifecycleStep OpenXrLifecycle::on_state(XrSessionState state) {
  state_ = state;
  switch (state) {
    case XR_SESSION_STATE_READY:
      if (exit_requested_ || leaving_) return LifecycleStep::Nothing;
      running_ = true;
      return LifecycleStep::BeginSession;
    case XR_SESSION_STATE_STOPPING:
      if (!running_) return LifecycleStep::Nothing;
      running_ = false;
      return LifecycleStep::EndSession;
    case XR_SESSION_STATE_EXITING:
      running_ = false;
      leaving_ = true;
      if (!exit_requested_) reason_ = "the OpenXR runtime ended the session (EXITING)";
      return LifecycleStep::Leave;
    case XR_SESSION_STATE_LOSS_PENDING:
      running_ = false;
      leaving_ = true;
      lost_ = true;
      reason_ = "the OpenXR session is being lost (LOSS_PENDING: the headset was disconnected?)";
      return LifecycleStep::Leave;
    default: return LifecycleStep::Nothing;
  }
}

LifecycleStep OpenXrLifecycle::on_instance_loss() {
  running_ = false;
  leaving_ = true;
  lost_ = true;
  reason_ = "the OpenXR runtime is going away (instance loss pending)";
  return LifecycleStep::Leave;
}

LifecycleStep OpenXrLifecycle::on_session_lost() {
  running_ = false;
  leaving_ = true;
  lost_ = true;
  reason_ = "the OpenXR session was lost (XR_ERROR_SESSION_LOST: the headset was disconnected?)";
  return LifecycleStep::Leave;
}

bool OpenXrLifecycle::request_exit() {
  if (exit_requested_ || leaving_) return false;
  exit_requested_ = true;
  if (running_) return true;
  // Never began (or already ended): nothing to wind down.
  leaving_ = true;
  return false;
}

const char* session_state_name(XrSessionState state) {
  switch (state) {
    case XR_SESSION_STATE_UNKNOWN: return "UNKNOWN";
    case XR_SESSION_STATE_IDLE: return "IDLE";
    case XR_SESSION_STATE_READY: return "READY";
    case XR_SESSION_STATE_SYNCHRONIZED: return "SYNCHRONIZED";
    case XR_SESSION_STATE_VISIBLE: return "VISIBLE";
    case XR_SESSION_STATE_FOCUSED: return "FOCUSED";
    case XR_SESSION_STATE_STOPPING: return "STOPPING";
    case XR_SESSION_STATE_LOSS_PENDING: return "LOSS_PENDING";
    case XR_SESSION_STATE_EXITING: return "EXITING";
    default: return "?";
  }
}

}  // namespace vdfx::xr
