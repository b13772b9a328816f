/// @file
/// @brief Session state machine, predicted display times and view location (GL-free).
#include "xr/headset/session.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdfx::xr {
namespace {

HmdProfile config(double hz) {
  HmdProfile p;
  p.name = "test";
  p.refresh_hz = hz;
  p.ipd_m = 0.064;
  for (auto& e : p.eyes) {
    e.width = 100;
    e.height = 100;
  }
  p.eyes[0].fov = {-50, 40, 45, -48};
  p.eyes[1].fov = {-40, 50, 45, -48};
  return p;
}

std::vector<SessionState> drain(Session& s, std::int64_t t) {
  std::vector<SessionState> out;
  while (auto e = s.poll_event(t)) out.push_back(e->state);
  return out;
}

using S = SessionState;

TEST(Session, LifecycleFollowsOpenXr) {
  Session s(config(90));
  EXPECT_EQ(s.state(), S::Idle);
  EXPECT_THROW(s.begin(0), SessionError);  // not READY yet
  EXPECT_EQ(drain(s, 0), (std::vector<S>{S::Ready}));
  s.begin(1000);
  EXPECT_EQ(drain(s, 1000), (std::vector<S>{S::Synchronized}));
  FrameState f = s.wait_frame(1000);
  EXPECT_FALSE(f.should_render);  // SYNCHRONIZED: frames are paced but not shown
  s.begin_frame();
  s.end_frame(f.predicted_display_time_ns, {});
  EXPECT_EQ(drain(s, 2000), (std::vector<S>{S::Visible, S::Focused}));
  f = s.wait_frame(2000);
  EXPECT_TRUE(f.should_render);
  s.begin_frame();
  s.end_frame(f.predicted_display_time_ns, {});
  s.set_input_focus(false, 3000);
  s.set_input_focus(true, 3001);
  EXPECT_EQ(drain(s, 3001), (std::vector<S>{S::Visible, S::Focused}));
  EXPECT_THROW(s.end(4000), SessionError);  // must request exit first
  s.request_exit(4000);
  EXPECT_EQ(drain(s, 4000), (std::vector<S>{S::Visible, S::Synchronized, S::Stopping}));
  s.end(5000);
  EXPECT_EQ(drain(s, 5000), (std::vector<S>{S::Idle, S::Exiting}));
  EXPECT_THROW(s.wait_frame(6000), SessionError);
}

const struct {
  const char* name;
  void (*misuse)(Session&, std::int64_t display);
} kMisuse[] = {
    {"wait twice", [](Session& s, std::int64_t) { s.wait_frame(10); }},
    {"end without begin", [](Session& s, std::int64_t d) { s.end_frame(d, {}); }},
    {"begin twice",
     [](Session& s, std::int64_t) {
       s.begin_frame();
       s.begin_frame();
     }},
    {"wrong display time",
     [](Session& s, std::int64_t d) {
       s.begin_frame();
       s.end_frame(d + 1, {});
     }},
};

TEST(Session, FrameCallsOutOfOrderAreRejectedWithTheState) {
  for (const auto& row : kMisuse) {
    Session s(config(90));
    drain(s, 0);
    s.begin(0);
    const FrameState f = s.wait_frame(0);
    try {
      row.misuse(s, f.predicted_display_time_ns);
      ADD_FAILURE() << row.name << ": no error";
    } catch (const SessionError& e) {
      EXPECT_NE(std::string(e.what()).find("state SYNCHRONIZED"), std::string::npos) << row.name;
    }
  }
}

const struct {
  double hz;
  std::int64_t now;       //!< ns since begin
  std::int64_t expected;  //!< predicted display time since begin
} kTiming[] = {
    {90, 0, 11111111},         // at a vsync: the next one
    {90, 5000000, 11111111},   // between vsyncs: the next one
    {90, 11111111, 22222222},  // exactly on a vsync: strictly after
    {72, 30000000, 41666667},  // 72 Hz, period 13.888889 ms rounded to ns
    {120, 100000000, 100000000 + 8333333 - 100000000 % 8333333},
};

TEST(Session, PredictedDisplayTimeIsTheNextVsync) {
  for (const auto& row : kTiming) {
    Session s(config(row.hz));
    drain(s, 0);
    const std::int64_t epoch = 1'000'000'000;
    s.begin(epoch);
    const FrameState f = s.wait_frame(epoch + row.now);
    const std::int64_t period = std::llround(1e9 / row.hz);
    EXPECT_EQ(f.predicted_display_period_ns, period) << row.hz;
    EXPECT_EQ(f.predicted_display_time_ns - epoch, row.expected) << row.hz << " Hz at " << row.now;
    EXPECT_EQ((f.predicted_display_time_ns - epoch) % period, 0);
  }
}

TEST(Session, FastFramesGetSuccessiveVsyncsAndLateFramesSkip) {
  Session s(config(90));
  drain(s, 0);
  s.begin(0);
  std::int64_t last = 0;
  for (int i = 0; i < 3; ++i) {  // an app that loops instantly still gets one vsync per frame
    const FrameState f = s.wait_frame(0);
    EXPECT_EQ(f.predicted_display_time_ns, (i + 1) * 11111111LL);
    EXPECT_EQ(f.wait_ns, std::max<std::int64_t>(0, f.predicted_display_time_ns - 11111111));
    s.begin_frame();
    s.end_frame(f.predicted_display_time_ns, {});
    last = f.predicted_display_time_ns;
  }
  const FrameState late = s.wait_frame(last + 5 * 11111111 + 7);  // missed vsyncs are skipped
  EXPECT_EQ(late.predicted_display_time_ns, last + 6 * 11111111LL);
  EXPECT_EQ(late.wait_ns, 0);
}

TEST(Session, ViewsCombineHeadPoseAndEyeOffsets) {
  Session s(config(90));
  Pose head;
  head.orientation = glm::angleAxis(M_PI / 2, glm::dvec3(0, 1, 0));  // turned left
  head.position = {0, 1.6, 0};
  const auto local = s.locate_views(head, ReferenceSpace::Local);
  // The right eye (+x in the head) of a head turned 90 degrees left sits at -z in LOCAL.
  EXPECT_LT((position_of(local[1].pose) - Eigen::Vector3d(0, 1.6, -0.032)).norm(), 1e-12);
  EXPECT_LT((position_of(local[0].pose) - Eigen::Vector3d(0, 1.6, 0.032)).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(local[0].fov.angle_left, -50);
  const auto view = s.locate_views(head, ReferenceSpace::View);
  EXPECT_LT((position_of(view[1].pose) - Eigen::Vector3d(0.032, 0, 0)).norm(), 1e-12);
  // The render view looks where the head looks: -z turned left is -x.
  const RenderView rv = render_view(local[0]);
  EXPECT_LT((rv.orientation * Eigen::Vector3d(0, 0, -1) - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR(rv.tan_left, std::tan(-50 * M_PI / 180), 1e-15);
  // A head-locked quad moves with the head.
  Pose quad;
  quad.position = {0, 0, -1};
  EXPECT_LT((position_of(Session::to_local(quad, ReferenceSpace::View, head)) -
             Eigen::Vector3d(-1, 1.6, 0))
                .norm(),
            1e-12);
  EXPECT_EQ(position_of(Session::to_local(quad, ReferenceSpace::Local, head)), position_of(quad));
}

TEST(Session, RejectsAnImpossibleRefreshRate) {
  EXPECT_THROW(Session(config(0.0)), SessionError);
}

}  // namespace
}  // namespace vdfx::xr
