/// @file
/// @brief The simulated runtime's session lifecycle and virtual clock, through the loader with
/// the core validation layer on: IDLE to FOCUSED and out to EXITING (the script's end, the app's
/// request, a frame limit), LOSS_PENDING at a time, the frame calls' order.
#include <gtest/gtest.h>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/openxr/xr_test_app.h"

namespace vdfx::test_runtime {
namespace {

using States = std::vector<XrSessionState>;

class Lifecycle : public RuntimeTest {};

/// Runs frames with no layers until STOPPING is queued; returns how many were waited.
int frames_until_stopping(XrTestApp& app, int limit) {
  for (int k = 0; k < limit; ++k) {
    app.empty_frame();
    for (const XrSessionState s : app.poll_states()) {
      if (s == XR_SESSION_STATE_STOPPING) return k + 1;
    }
  }
  return -1;
}

TEST_F(Lifecycle, FromIdleToFocusedAndOutToExitingWhenTheScriptEnds) {
  // A script of 100 ms: frame 9 (99.999999 ms) is the last inside it, frame 10 the first past it.
  script({{0, 0.0}, {50'000'000, 10.0}, {100'000'000, 20.0}});
  XrTestApp app;
  ASSERT_TRUE(app.start());
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY}));
  ASSERT_EQ(XR_EXPECT_OK(app.begin_session()), XR_SUCCESS);
  // Frame 0: the loop runs (SYNCHRONIZED), nothing is shown yet.
  const XrFrameState first = app.wait_frame();
  EXPECT_EQ(first.predictedDisplayTime, frame_time(0));
  EXPECT_EQ(first.predictedDisplayPeriod, 11111111);  // generic90: 90 Hz
  EXPECT_FALSE(first.shouldRender);
  XR_EXPECT_OK(app.begin_frame());
  XR_EXPECT_OK(app.end_frame({}, first.predictedDisplayTime));
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE,
                                       XR_SESSION_STATE_FOCUSED}));
  // Every frame is one display period later, whatever the wall clock did.
  for (int k = 1; k <= 9; ++k) {
    const XrFrameState s = app.empty_frame();
    EXPECT_EQ(s.predictedDisplayTime, frame_time(k));
    EXPECT_TRUE(s.shouldRender);
    EXPECT_TRUE(app.poll_states().empty());
  }
  app.empty_frame();  // frame 10, past the script's last sample
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_SYNCHRONIZED,
                                       XR_SESSION_STATE_STOPPING}));
  XR_EXPECT_OK(xrEndSession(app.session));
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  const auto session = session_json();
  EXPECT_EQ(session.at("frames_waited"), 11);
  ASSERT_EQ(session.at("states").size(), 10u);
  EXPECT_EQ(session.at("states").back().at("state"), "XR_SESSION_STATE_EXITING");
  EXPECT_EQ(session.at("states").back().at("time_ns"), frame_time(10));
}

TEST_F(Lifecycle, TheAppsRequestToExitGoesThroughStoppingToExiting) {
  XrTestApp app;  // no script: the session runs until the app leaves
  ASSERT_TRUE(app.start());
  ASSERT_TRUE(app.poll_until(XR_SESSION_STATE_READY));
  XR_EXPECT_OK(app.begin_session());
  for (int k = 0; k < 3; ++k) app.empty_frame();
  ASSERT_EQ(app.poll_states().back(), XR_SESSION_STATE_FOCUSED);
  // Not STOPPING yet: ending the session is refused.
  EXPECT_EQ(xrEndSession(app.session), XR_ERROR_SESSION_NOT_STOPPING);
  XR_EXPECT_OK(xrRequestExitSession(app.session));
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_SYNCHRONIZED,
                                       XR_SESSION_STATE_STOPPING}));
  // Frames may still run until xrEndSession; they are not shown.
  EXPECT_FALSE(app.empty_frame().shouldRender);
  XR_EXPECT_OK(xrEndSession(app.session));
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
}

TEST_F(Lifecycle, AFrameLimitEndsAScriptlessSession) {
  set("VDFX_TEST_RUNTIME_EXIT_AFTER_FRAMES", "4");
  XrTestApp app;
  ASSERT_TRUE(app.start());
  app.poll_states();
  XR_EXPECT_OK(app.begin_session());
  // Frames 0-3 run; waiting frame 4 starts the way out.
  EXPECT_EQ(frames_until_stopping(app, 10), 5);
}

TEST_F(Lifecycle, LossPendingAtTheScriptedTime) {
  set("VDFX_TEST_RUNTIME_LOSS_PENDING_NS", "50000000");  // frame 5 (55.6 ms) is the first at it
  XrTestApp app;
  ASSERT_TRUE(app.start());
  app.poll_states();
  XR_EXPECT_OK(app.begin_session());
  for (int k = 0; k < 5; ++k) app.empty_frame();
  EXPECT_EQ(app.poll_states().back(), XR_SESSION_STATE_FOCUSED);
  XrFrameState state{};
  state.type = XR_TYPE_FRAME_STATE;
  EXPECT_EQ(xrWaitFrame(app.session, nullptr, &state), XR_SESSION_LOSS_PENDING);
  EXPECT_EQ(app.poll_states(), (States{XR_SESSION_STATE_LOSS_PENDING}));
  EXPECT_EQ(app.begin_frame(), XR_SESSION_LOSS_PENDING);
  EXPECT_EQ(app.end_frame({}, state.predictedDisplayTime), XR_SESSION_LOSS_PENDING);
  // The session is as good as lost: the app can only destroy it.
  EXPECT_EQ(xrRequestExitSession(app.session), XR_ERROR_SESSION_LOST);
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  EXPECT_EQ(session_json().at("states").back().at("state"), "XR_SESSION_STATE_LOSS_PENDING");
}

class LifecycleWithoutLayer : public RuntimeTest {};

TEST_F(LifecycleWithoutLayer, FrameCallsOutOfOrderAreRefused) {
  without_layer();  // the layer would refuse some of these before the runtime sees them
  XrTestApp app;
  ASSERT_TRUE(app.start());
  app.poll_states();
  XrFrameState state{};
  state.type = XR_TYPE_FRAME_STATE;
  EXPECT_EQ(xrWaitFrame(app.session, nullptr, &state), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(xrEndSession(app.session), XR_ERROR_SESSION_NOT_RUNNING);
  XR_EXPECT_OK(app.begin_session());
  EXPECT_EQ(app.begin_session(), XR_ERROR_SESSION_RUNNING);
  EXPECT_EQ(app.begin_frame(), XR_ERROR_CALL_ORDER_INVALID);  // no xrWaitFrame yet
  EXPECT_EQ(app.end_frame({}, frame_time(0)), XR_ERROR_CALL_ORDER_INVALID);
  state = app.wait_frame();
  EXPECT_EQ(app.begin_frame(), XR_SUCCESS);
  state = app.wait_frame();
  // Beginning the next frame before ending this one discards this one.
  EXPECT_EQ(app.begin_frame(), XR_FRAME_DISCARDED);
  EXPECT_EQ(app.end_frame({}, 0), XR_ERROR_TIME_INVALID);
  XrFrameEndInfo additive{};
  additive.type = XR_TYPE_FRAME_END_INFO;
  additive.displayTime = state.predictedDisplayTime;
  additive.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_ADDITIVE;
  EXPECT_EQ(xrEndFrame(app.session, &additive), XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED);
  EXPECT_EQ(app.end_frame({}, state.predictedDisplayTime), XR_SUCCESS);
}

}  // namespace
}  // namespace vdfx::test_runtime
