/// @file
/// @brief The world anchor on the GPU (`vdfx render --gpu`, view and per-pixel mode: the
/// compositor's effect stack and its parameter grid) on the turning clip: at each frame the view
/// at the window's direction of the video frame has the window's exposure within 0.05 stops, as
/// the CPU render has (tests/app/anchor_turn_test.cpp).
#include <gtest/gtest.h>

#include "app/export/view_render.h"
#include "io/sidecar.h"
#include "tests/app/turning_clip_files.h"

namespace vdfx::app {
namespace {

cv::Mat render_window_gpu(const std::filesystem::path& sidecar, int f, effects::RenderMode mode) {
  RenderRequest r;
  r.look = testing::turning_window_at(f);
  r.frame = f;
  r.hfov_deg = 20.0;
  r.width = r.height = 32;
  r.mode = mode;
  r.gpu = true;
  r.bake_width = 256;
  r.bake_height = 128;
  cv::Mat out;
  render_request(testing::turning_clip_files().video, io::read_sidecar(sidecar), r)
      .convertTo(out, CV_32FC3);
  return out;
}

TEST(AnchorRenderGl, TheGpuAppliesTheWindowsExposureAtEveryFrameInBothModes) {
  const testing::TurningClipFiles& c = testing::turning_clip_files();
  for (const effects::RenderMode mode : {effects::RenderMode::View, effects::RenderMode::Pixel}) {
    for (const int f : {0, 3, 5, 7}) {
      SCOPED_TRACE("frame " + std::to_string(f) +
                   (mode == effects::RenderMode::View ? " view" : " pixel"));
      const cv::Mat plain = render_window_gpu(c.plain, f, mode);
      EXPECT_NEAR(testing::applied_stops(render_window_gpu(c.anchored, f, mode), plain),
                  bench::kWindowStops, 0.05);
      // Fixed in the picture, the keyframe has left the window once the camera turned.
      if (f >= 3) {
        EXPECT_GT(std::abs(testing::applied_stops(render_window_gpu(c.fixed, f, mode), plain) -
                           bench::kWindowStops),
                  0.5);
      }
    }
  }
}

}  // namespace
}  // namespace vdfx::app
