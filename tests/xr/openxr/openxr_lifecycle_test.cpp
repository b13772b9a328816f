/// @file
/// @brief The OpenXR session lifecycle as vdfx steps it: the calls each state asks for, and
/// when and why the loop ends.
#include "xr/openxr/openxr_lifecycle.h"

#include <gtest/gtest.h>

namespace vdfx::xr {
namespace {

TEST(OpenXrLifecycle, IdleToFocusedAndOutWhenVdfxAsksToLeave) {
  OpenXrLifecycle l;
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_IDLE), LifecycleStep::Nothing);
  EXPECT_FALSE(l.running());
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_READY), LifecycleStep::BeginSession);
  EXPECT_TRUE(l.running());
  for (auto s : {XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_FOCUSED})
    EXPECT_EQ(l.on_state(s), LifecycleStep::Nothing);
  EXPECT_STREQ(session_state_name(l.state()), "FOCUSED");
  EXPECT_TRUE(l.request_exit());   // xrRequestExitSession now
  EXPECT_FALSE(l.request_exit());  // once
  EXPECT_FALSE(l.leaving());       // the runtime walks the states down first
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_VISIBLE), LifecycleStep::Nothing);
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_STOPPING), LifecycleStep::EndSession);
  EXPECT_FALSE(l.running());
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_IDLE), LifecycleStep::Nothing);
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_EXITING), LifecycleStep::Leave);
  EXPECT_TRUE(l.leaving());
  EXPECT_FALSE(l.lost());
  EXPECT_EQ(l.reason(), "");  // vdfx asked: nothing to explain
}

TEST(OpenXrLifecycle, RuntimeStoppingAndExitingIsExplained) {
  OpenXrLifecycle l;
  l.on_state(XR_SESSION_STATE_READY);
  l.on_state(XR_SESSION_STATE_FOCUSED);
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_STOPPING), LifecycleStep::EndSession);
  l.on_state(XR_SESSION_STATE_IDLE);
  EXPECT_FALSE(l.leaving());  // IDLE: the runtime may make it READY again
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_READY), LifecycleStep::BeginSession);
  l.on_state(XR_SESSION_STATE_STOPPING);
  l.on_state(XR_SESSION_STATE_IDLE);
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_EXITING), LifecycleStep::Leave);
  EXPECT_NE(l.reason().find("EXITING"), std::string::npos);
}

TEST(OpenXrLifecycle, LossPendingLeavesAtOnceWithoutEndingTheSession) {
  OpenXrLifecycle l;
  l.on_state(XR_SESSION_STATE_READY);
  l.on_state(XR_SESSION_STATE_FOCUSED);
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_LOSS_PENDING), LifecycleStep::Leave);
  EXPECT_TRUE(l.leaving());
  EXPECT_TRUE(l.lost());
  EXPECT_FALSE(l.running());
  EXPECT_NE(l.reason().find("LOSS_PENDING"), std::string::npos);
  EXPECT_FALSE(l.request_exit());  // nothing left to ask
}

TEST(OpenXrLifecycle, InstanceLossLeaves) {
  OpenXrLifecycle l;
  l.on_state(XR_SESSION_STATE_READY);
  EXPECT_EQ(l.on_instance_loss(), LifecycleStep::Leave);
  EXPECT_TRUE(l.lost());
  EXPECT_TRUE(l.leaving());
}

TEST(OpenXrLifecycle, SessionLostByACallLeaves) {
  OpenXrLifecycle l;
  l.on_state(XR_SESSION_STATE_READY);
  l.on_state(XR_SESSION_STATE_FOCUSED);
  EXPECT_EQ(l.on_session_lost(), LifecycleStep::Leave);
  EXPECT_TRUE(l.lost());
  EXPECT_FALSE(l.running());
  EXPECT_NE(l.reason().find("XR_ERROR_SESSION_LOST"), std::string::npos);
}

TEST(OpenXrLifecycle, LeavingBeforeTheSessionRanNeedsNoRequest) {
  OpenXrLifecycle l;
  l.on_state(XR_SESSION_STATE_IDLE);
  EXPECT_FALSE(l.request_exit());
  EXPECT_TRUE(l.leaving());
  // A READY arriving after that does not begin a session vdfx is leaving.
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_READY), LifecycleStep::Nothing);
  EXPECT_FALSE(l.running());
}

TEST(OpenXrLifecycle, StoppingWithoutBeginIsNotEnded) {
  OpenXrLifecycle l;
  EXPECT_EQ(l.on_state(XR_SESSION_STATE_STOPPING), LifecycleStep::Nothing);
}

}  // namespace
}  // namespace vdfx::xr
