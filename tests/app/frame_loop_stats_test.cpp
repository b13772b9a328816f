/// @file
/// @brief --stats accumulation: eyes summed per stage, medians per window and in total.
#include "app/window/frame_loop_stats.h"

#include <gtest/gtest.h>

namespace vdfx::app {
namespace {

double find(const std::vector<StageMedian>& m, const std::string& stage) {
  for (const auto& s : m)
    if (s.stage == stage) return s.ms;
  ADD_FAILURE() << "no stage " << stage;
  return -1;
}

TEST(FrameLoopStats, EyesSummedAndMedians) {
  FrameLoopStats s;
  const double video[] = {3.0, 1.0, 100.0};
  for (double v : video) {
    s.add_gpu({{"left video", v},
               {"right video", v},
               {"left distortion", 0.5},
               {"right distortion", 0.25}});
    s.add_cpu("frame", v * 10);
  }
  const auto w = s.take_window();
  EXPECT_DOUBLE_EQ(find(w, "gpu video"), 6.0);  // median of 2, 6, 200 per frame (both eyes)
  EXPECT_DOUBLE_EQ(find(w, "gpu distortion"), 0.75);
  EXPECT_DOUBLE_EQ(find(w, "cpu frame"), 30.0);
  EXPECT_EQ(w.front().stage, "gpu video");  // pipeline order first
  s.add_gpu({{"left video", 2.0}, {"right video", 2.0}});
  const auto w2 = s.take_window();
  EXPECT_DOUBLE_EQ(find(w2, "gpu video"), 4.0);
  EXPECT_DOUBLE_EQ(find(s.total(), "gpu video"), 5.0);  // median of 2, 4, 6, 200
  EXPECT_NE(FrameLoopStats::format(w).find("gpu video 6.00 ms"), std::string::npos);
}

}  // namespace
}  // namespace vdfx::app
