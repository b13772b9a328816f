/// @file
/// @brief Playhead: exact display time -> frame, pause, seek, loop.
#include "app/window/player_playhead.h"

#include <gtest/gtest.h>

namespace vdfx::app {
namespace {

TEST(PlayerPlayhead, FrameFollowsDisplayTimeExactlyWithoutDrift) {
  // 29.97 fps for 10 hours of 90 Hz vsyncs: the frame is frame_at_time of the elapsed time.
  const io::Rational fps{30000, 1001};
  const std::int64_t frames = 2000000;
  Playhead p(fps, frames, false);
  const std::int64_t t0 = 123456789;
  const std::int64_t period = 11111111;
  for (std::int64_t k : {0LL, 1LL, 2LL, 89LL, 90LL, 324000LL, 3240000LL}) {
    const std::int64_t t = t0 + k * period;
    EXPECT_EQ(p.frame_at(t), io::frame_at_time(k * period, fps)) << k;
  }
  // At exactly each frame's start (rounded ns) the frame is that frame, 10 h in.
  const std::int64_t f = 1078920;
  EXPECT_EQ(p.frame_at(t0 + io::frame_start_ns(f, fps)), f);
  EXPECT_EQ(p.frame_at(t0 + io::frame_start_ns(f, fps) - 1), f - 1);
}

TEST(PlayerPlayhead, PauseHoldsTheFrameAndResumesFromIt) {
  Playhead p({30, 1}, 300, false);
  EXPECT_EQ(p.frame_at(0), 0);
  EXPECT_EQ(p.frame_at(1'000'000'000), 30);
  p.set_paused(true, 1'000'000'000);
  EXPECT_EQ(p.frame_at(5'000'000'000), 30);
  p.set_paused(false, 5'000'000'000);
  EXPECT_EQ(p.frame_at(5'000'000'000), 30);
  EXPECT_EQ(p.frame_at(6'000'000'000), 60);
}

TEST(PlayerPlayhead, SeekAndLoop) {
  const struct {
    bool loop;
    std::int64_t start_s, delta, expect;
  } rows[] = {
      {false, 1, 150, 180}, {false, 1, -60, 0}, {false, 9, 150, 299},
      {true, 1, -60, 270},  {true, 9, 50, 20},
  };
  for (const auto& r : rows) {
    Playhead p({30, 1}, 300, r.loop);
    p.frame_at(0);
    const std::int64_t t = r.start_s * 1'000'000'000;
    p.seek_by(r.delta, t);
    EXPECT_EQ(p.frame_at(t), r.expect) << r.loop << " " << r.start_s << " " << r.delta;
  }
  // Looping wraps the video time; turning looping off keeps the frame on screen.
  Playhead p({30, 1}, 300, true);
  p.frame_at(0);
  EXPECT_EQ(p.frame_at(11'000'000'000), 30);
  p.set_loop(false, 11'000'000'000);
  EXPECT_EQ(p.frame_at(11'000'000'000), 30);
  EXPECT_EQ(p.frame_at(30'000'000'000), 299);
}

}  // namespace
}  // namespace vdfx::app
