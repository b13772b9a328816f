/// @file
/// @brief The headset display's refresh rate: measured from predicted display times past a
/// runtime's placeholder frames, a skipped frame not moving it, and the report's wording.
#include "xr/openxr/display_refresh.h"

#include <gtest/gtest.h>

#include <vector>

namespace vdfx::xr {
namespace {

/// Display times: `placeholder` frames 16 ms apart (Monado's first frames), then `period`.
std::vector<std::int64_t> times(int placeholder, int frames, std::int64_t period) {
  std::vector<std::int64_t> t;
  std::int64_t now = 1'000'000'000;
  for (int k = 0; k < placeholder + frames; ++k) {
    t.push_back(now);
    now += k < placeholder ? 16'000'000 : period;
  }
  return t;
}

TEST(DisplayRefresh, MeasuredPastThePlaceholderFrames) {
  struct Row {
    const char* name;
    int placeholder, frames;
    std::int64_t period;
    double hz;
  };
  const Row rows[] = {
      {"90 Hz after 5 placeholder frames", 5, 36, 11'111'111, 90.0},
      {"120 Hz from the start", 0, 41, 8'333'333, 120.0},
      {"72 Hz after 10", 10, 31, 13'888'889, 72.0},
  };
  for (const Row& r : rows) {
    SCOPED_TRACE(r.name);
    const auto hz =
        refresh_from_display_times(times(r.placeholder, r.frames, r.period), kRefreshWarmupFrames);
    ASSERT_TRUE(hz.has_value());
    EXPECT_NEAR(*hz, r.hz, 1e-3);
  }
  // Without the warm-up skipped, more placeholder frames than measured ones would win.
  const auto naive = refresh_from_display_times(times(30, 10, 11'111'111), 0);
  ASSERT_TRUE(naive.has_value());
  EXPECT_NEAR(*naive, 62.5, 1e-9) << "the placeholder's rate: why the warm-up is skipped";
}

TEST(DisplayRefresh, ASkippedFrameDoesNotMoveTheMedian) {
  std::vector<std::int64_t> t = times(0, 41, 11'111'111);
  for (std::size_t i = 20; i < t.size(); ++i) t[i] += 11'111'111;  // frame 20 came a period late
  const auto hz = refresh_from_display_times(t, kRefreshWarmupFrames);
  ASSERT_TRUE(hz.has_value());
  EXPECT_NEAR(*hz, 90.0, 1e-3);
}

TEST(DisplayRefresh, TooFewOrStillTimesAreNoRate) {
  EXPECT_FALSE(refresh_from_display_times(times(0, 11, 11'111'111), 10).has_value());
  EXPECT_TRUE(refresh_from_display_times(times(0, 12, 11'111'111), 10).has_value());
  EXPECT_FALSE(refresh_from_display_times(std::vector<std::int64_t>(20, 5), 0).has_value());
}

TEST(DisplayRefresh, TheReportSaysWhereTheRateCameFrom) {
  DisplayRefresh ext;
  ext.hz = 90.0f;
  ext.offered_hz = {72.0, 90.0, 120.0};
  ext.from_extension = true;
  EXPECT_EQ(describe_refresh(ext),
            "90 Hz (XR_FB_display_refresh_rate; the display offers 72, 90, 120 Hz)");
  DisplayRefresh measured;
  measured.hz = 1e9 / 11'111'111.0;
  measured.measured_intervals = 30;
  EXPECT_EQ(describe_refresh(measured),
            "90 Hz (measured: the median interval of the display times the runtime predicted for "
            "30 frames; it offers no XR_FB_display_refresh_rate)");
  EXPECT_EQ(describe_refresh(DisplayRefresh{}),
            "unknown (the session did not run frames within 2 s)");
  EXPECT_EQ(hz_text(59.94006), "59.94");
  EXPECT_EQ(hz_text(72.5), "72.5");
}

}  // namespace
}  // namespace vdfx::xr
