/// @file
/// @brief Exact time -> frame mapping over hours of NTSC-rate playback.
#include "io/frame_time.h"

#include <gtest/gtest.h>

namespace vdfx::io {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;
constexpr std::int64_t kHour = 3600 * kSecond;

TEST(FrameTime, RecoversRationalRates) {
  EXPECT_EQ(fps_to_rational(30000.0 / 1001.0), (Rational{30000, 1001}));
  EXPECT_EQ(fps_to_rational(24000.0 / 1001.0), (Rational{24000, 1001}));
  EXPECT_EQ(fps_to_rational(60000.0 / 1001.0), (Rational{60000, 1001}));
  EXPECT_EQ(fps_to_rational(25.0), (Rational{25, 1}));
  EXPECT_EQ(fps_to_rational(29.97), (Rational{2997, 100}));
  EXPECT_EQ(fps_to_rational(12.5), (Rational{25, 2}));
  EXPECT_THROW(fps_to_rational(0.0), std::invalid_argument);
  EXPECT_THROW(fps_to_rational(-1.0), std::invalid_argument);
}

struct HourCase {
  Rational fps;
  std::int64_t t_ns;
  std::int64_t frame;  //!< floor(seconds * num / den), worked out by hand
};

// 3600 * 30000 / 1001 = 107892.107..., 36000 * 30000 / 1001 = 1078921.078...
// 3600 * 24000 / 1001 = 86313.686...,   36000 * 24000 / 1001 = 863136.863...
const HourCase kHours[] = {
    {{30000, 1001}, kHour, 107892}, {{30000, 1001}, 10 * kHour, 1078921},
    {{24000, 1001}, kHour, 86313},  {{24000, 1001}, 10 * kHour, 863136},
    {{25, 1}, 10 * kHour, 900000},  {{30000, 1001}, 0, 0},
};

TEST(FrameTime, ExactAtHours) {
  for (const HourCase& c : kHours)
    EXPECT_EQ(frame_at_time(c.t_ns, c.fps), c.frame) << c.fps.num << "/" << c.fps.den;
}

TEST(FrameTime, FrameStartsMapToTheirFrameAndOneNanosecondEarlierToThePrevious) {
  for (const Rational fps : {Rational{30000, 1001}, Rational{24000, 1001}, Rational{60, 1}}) {
    for (const std::int64_t k :
         {std::int64_t{1}, std::int64_t{2}, std::int64_t{1000}, std::int64_t{107892},
          std::int64_t{1078920}, std::int64_t{1078921}, std::int64_t{2000003}}) {
      const std::int64_t s = frame_start_ns(k, fps);
      EXPECT_EQ(frame_at_time(s, fps), k) << k;
      EXPECT_EQ(frame_at_time(s - 1, fps), k - 1) << k;
      // Frame durations at these rates are ~16.7 to ~41.7 ms.
      const std::int64_t next = frame_start_ns(k + 1, fps);
      EXPECT_GT(next - s, 16'000'000);
      EXPECT_EQ(frame_at_time(next - 2, fps), k);
    }
  }
}

TEST(FrameTime, ExactAtFrameStartsOverTenHours) {
  // Every frame start over 10 h of 29.97 fps (spot-checked every 9973 frames).
  const Rational fps{30000, 1001};
  for (std::int64_t k = 0; k < 1100000; k += 9973)
    EXPECT_EQ(frame_at_time(frame_start_ns(k, fps), fps), k);
}

TEST(FrameTime, PlaybackFrameLoopsOrClamps) {
  const Rational fps{30, 1};
  EXPECT_EQ(playback_frame(kSecond, fps, 20, true), 10);
  EXPECT_EQ(playback_frame(kSecond, fps, 20, false), 19);
  EXPECT_EQ(playback_frame(-kSecond / 30, fps, 20, true), 19);
  EXPECT_EQ(playback_frame(-kSecond, fps, 20, false), 0);
  EXPECT_EQ(playback_frame(10 * kHour, Rational{30000, 1001}, 900, true), 1078921 % 900);
}

}  // namespace
}  // namespace vdfx::io
