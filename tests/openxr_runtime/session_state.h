/// @file
/// @brief The session's state machine and the instance's event queue, shared by the entry points
/// that move them (session.cpp, frame.cpp, actions.cpp).
#pragma once

#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

/// Queues an event (any XrEventData* struct) for xrPollEvent; beyond kMaxQueuedEvents the oldest
/// are dropped and counted, and the next poll reports XrEventDataEventsLost.
void push_event(Instance& inst, const void* event, std::size_t size);
XrResult pop_event(Instance& inst, XrEventDataBuffer& out);

/// Moves the session to `state` and queues XrEventDataSessionStateChanged at the session's time.
void set_session_state(Instance& inst, Session& s, XrSessionState state);

/// Starts the way out (xrRequestExitSession, the script's end, the frame limit): through VISIBLE
/// and SYNCHRONIZED as needed to STOPPING; xrEndSession then gives IDLE and EXITING.
void begin_exit(Instance& inst, Session& s);

/// Frees the session's GL objects (in the app's context), writes its read-back files and drops it.
void destroy_session(Instance& inst);

}  // namespace vdfx::test_runtime
