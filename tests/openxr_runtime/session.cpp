/// @file
/// @brief The session's lifecycle (spec 9.3 "Session Lifecycle"): IDLE and READY at creation,
/// SYNCHRONIZED at the first xrWaitFrame, VISIBLE and FOCUSED once a frame is submitted,
/// STOPPING when the app or the script asks to leave, then IDLE and EXITING after xrEndSession;
/// LOSS_PENDING on request. The events go through the instance's queue (xrPollEvent).
#include <algorithm>
#include <cstring>

#include "tests/openxr_runtime/capture.h"
#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/gl_context.h"
#include "tests/openxr_runtime/session_state.h"
#include "tests/openxr_runtime/swapchain_gl.h"

namespace vdfx::test_runtime {

void push_event(Instance& inst, const void* event, std::size_t size) {
  XrEventDataBuffer buffer{};
  std::memcpy(&buffer, event, std::min(size, sizeof buffer));
  if (inst.events.size() >= kMaxQueuedEvents) {
    inst.events.pop_front();
    ++inst.events_lost;
  }
  inst.events.push_back(buffer);
}

XrResult pop_event(Instance& inst, XrEventDataBuffer& out) {
  if (inst.events_lost > 0) {
    XrEventDataEventsLost lost{};
    lost.type = XR_TYPE_EVENT_DATA_EVENTS_LOST;
    lost.lostEventCount = inst.events_lost;
    inst.events_lost = 0;
    std::memcpy(&out, &lost, sizeof lost);
    return XR_SUCCESS;
  }
  if (inst.events.empty()) return XR_EVENT_UNAVAILABLE;
  out = inst.events.front();
  inst.events.pop_front();
  return XR_SUCCESS;
}

void set_session_state(Instance& inst, Session& s, XrSessionState state) {
  s.state = state;
  XrEventDataSessionStateChanged e{};
  e.type = XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED;
  e.session = to_handle<XrSession>(&s);
  e.state = state;
  e.time = s.now;
  push_event(inst, &e, sizeof e);
  if (s.recorder) s.recorder->state(state, s.now);
}

void begin_exit(Instance& inst, Session& s) {
  if (s.exit_begun || s.state == XR_SESSION_STATE_LOSS_PENDING) return;
  s.exit_begun = true;
  if (s.state == XR_SESSION_STATE_READY) set_session_state(inst, s, XR_SESSION_STATE_SYNCHRONIZED);
  if (s.state == XR_SESSION_STATE_FOCUSED) set_session_state(inst, s, XR_SESSION_STATE_VISIBLE);
  if (s.state == XR_SESSION_STATE_VISIBLE)
    set_session_state(inst, s, XR_SESSION_STATE_SYNCHRONIZED);
  set_session_state(inst, s, XR_SESSION_STATE_STOPPING);
}

void destroy_session(Instance& inst) {
  Session& s = *inst.session;
  const bool kept = s.recorder && s.recorder->kept();
  if (!s.swapchains.empty() || s.own_context || kept) {
    {
      GlContextScope scope(s);
      if (kept) {
        for (auto& layer : s.recorder->kept()->layers) {
          for (auto& view : layer.views) resolve_copy(view);
        }
      }
      for (auto& sc : s.swapchains) delete_swapchain_textures(*sc);
    }
    destroy_own_context(s);
  }
  if (s.recorder) {
    try {
      s.recorder->finish(s.waits, s.frames_ended);
    } catch (const std::exception& e) {
      // The session goes anyway; the missing session.json tells the test.
      fail("xrDestroySession", XR_ERROR_RUNTIME_FAILURE, e.what());
    }
  }
  const XrSession handle = to_handle<XrSession>(&s);
  std::erase_if(inst.events, [&](const XrEventDataBuffer& e) {
    return e.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED &&
           reinterpret_cast<const XrEventDataSessionStateChanged&>(e).session == handle;
  });
  inst.session.reset();
}

namespace api {
namespace {

XrResult read_gl_binding(const char* fn, const Instance& inst, const XrSessionCreateInfo& info,
                         GlBinding& out) {
  const XrGraphicsBindingOpenGLXlibKHR* binding = nullptr;
  for (auto* n = static_cast<const XrBaseInStructure*>(info.next); n; n = n->next) {
    if (n->type == XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR) {
      binding = reinterpret_cast<const XrGraphicsBindingOpenGLXlibKHR*>(n);
    }
  }
  if (!inst.gl_enabled || !binding) {
    return fail(fn, XR_ERROR_GRAPHICS_DEVICE_INVALID,
                "the runtime renders through OpenGL only: enable XR_KHR_opengl_enable and chain "
                "an XrGraphicsBindingOpenGLXlibKHR");
  }
  if (!inst.gl_requirements_queried) {
    return fail(fn, XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING,
                "xrGetOpenGLGraphicsRequirementsKHR was not called first");
  }
  if (!binding->xDisplay || !binding->glxContext || !binding->glxDrawable) {
    return fail(fn, XR_ERROR_GRAPHICS_DEVICE_INVALID,
                "the GL binding's xDisplay, glxDrawable or glxContext is null");
  }
  out = {binding->xDisplay, binding->glxFBConfig, binding->glxDrawable, binding->glxContext};
  return XR_SUCCESS;
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrCreateSession(XrInstance instance, const XrSessionCreateInfo* info,
                                               XrSession* session) {
  constexpr const char* fn = "xrCreateSession";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_SESSION_CREATE_INFO,
                              {XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR});
    if (XR_FAILED(r)) return r;
    if (!session) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "session is null");
    if (info->systemId != kSystemId || !inst->system_found) {
      return fail(fn, XR_ERROR_SYSTEM_INVALID, "systemId was not returned by xrGetSystem");
    }
    if (inst->session) return fail(fn, XR_ERROR_LIMIT_REACHED, "one session at a time");
    GlBinding gl;
    r = read_gl_binding(fn, *inst, *info, gl);
    if (XR_FAILED(r)) return r;
    // No struct extends the binding: a second one chained after it is an error.
    r = check_struct(fn, "createInfo->next", info->next, XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR);
    if (XR_FAILED(r)) return r;
    auto s = std::make_unique<Session>();
    s->gl = gl;
    s->switch_context = inst->config.switch_gl_context;
    if (!inst->config.output_dir.empty()) s->recorder = std::make_unique<Recorder>(*inst);
    inst->session = std::move(s);
    Session& created = *inst->session;
    set_session_state(*inst, created, XR_SESSION_STATE_IDLE);
    set_session_state(*inst, created, XR_SESSION_STATE_READY);
    *session = to_handle<XrSession>(&created);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrDestroySession(XrSession session) {
  return guarded("xrDestroySession", [&] {
    Session* s = find_session(session);
    if (!s) return fail("xrDestroySession", XR_ERROR_HANDLE_INVALID, "unknown session");
    if (s->recorder) s->recorder->call("xrDestroySession", s->waits);
    destroy_session(*live_instance());
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrBeginSession(XrSession session, const XrSessionBeginInfo* info) {
  constexpr const char* fn = "xrBeginSession";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r = check_struct(fn, "beginInfo", info, XR_TYPE_SESSION_BEGIN_INFO);
    if (XR_FAILED(r)) return r;
    if (s->running) return fail(fn, XR_ERROR_SESSION_RUNNING, "the session is running");
    if (s->state == XR_SESSION_STATE_LOSS_PENDING) return XR_ERROR_SESSION_LOST;
    if (s->state != XR_SESSION_STATE_READY) {
      return fail(fn, XR_ERROR_SESSION_NOT_READY,
                  "the session is " + session_state_name(s->state) + ", not READY");
    }
    if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) {
      return fail(fn, XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED,
                  "the simulated headset has the stereo view configuration only");
    }
    s->view_config = info->primaryViewConfigurationType;
    if (s->recorder) s->recorder->call(fn, s->waits);
    s->running = true;
    s->waits = s->begins = 0;
    s->in_frame = false;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEndSession(XrSession session) {
  constexpr const char* fn = "xrEndSession";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    if (s->state == XR_SESSION_STATE_LOSS_PENDING) return XR_ERROR_SESSION_LOST;
    if (!s->running) return fail(fn, XR_ERROR_SESSION_NOT_RUNNING, "the session is not running");
    if (s->state != XR_SESSION_STATE_STOPPING) {
      return fail(fn, XR_ERROR_SESSION_NOT_STOPPING,
                  "the session is " + session_state_name(s->state) + ", not STOPPING");
    }
    if (s->recorder) s->recorder->call(fn, s->waits);
    s->running = false;
    s->in_frame = false;
    Instance& inst = *live_instance();
    set_session_state(inst, *s, XR_SESSION_STATE_IDLE);
    // Every way to STOPPING here is a way out (the app's request, the script's end), so the
    // session goes on to EXITING, as after xrRequestExitSession.
    set_session_state(inst, *s, XR_SESSION_STATE_EXITING);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrRequestExitSession(XrSession session) {
  constexpr const char* fn = "xrRequestExitSession";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    if (s->state == XR_SESSION_STATE_LOSS_PENDING) return XR_ERROR_SESSION_LOST;
    if (!s->running) return fail(fn, XR_ERROR_SESSION_NOT_RUNNING, "the session is not running");
    if (s->recorder) s->recorder->call(fn, s->waits);
    begin_exit(*live_instance(), *s);
    return XR_SUCCESS;
  });
}

}  // namespace api
}  // namespace vdfx::test_runtime
