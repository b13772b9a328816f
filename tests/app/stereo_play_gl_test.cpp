/// @file
/// @brief The windowed loop on stereo video (docs/stereo.md): each eye's buffer shows its own
/// half of a top-bottom H.264 frame (the Y'CbCr planes cut per eye on the GPU path, and the RGB
/// path of a still), the desktop view shows the left eye and key 5 switches it to the right.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/window/frame_loop.h"
#include "app/window/player.h"
#include "io/video_source.h"
#include "player_test_support.h"
#include "tests/media_clips.h"
#include "tests/test_files.h"
#include "xr/input/input_backend.h"
#include "xr/render/compositor.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

/// A top-bottom clip (or PNG still): the left eye red, the right eye blue (RGB).
fs::path red_blue(const fs::path& dir, const std::string& name) {
  cv::Mat frame(128, 128, CV_8UC3, cv::Scalar(255, 0, 0));
  frame.rowRange(64, 128).setTo(cv::Scalar(0, 0, 255));
  test_media::ClipSpec c;
  c.width = 128;
  c.height = 128;
  c.frames = 12;
  c.frame = [frame](int) { return frame; };
  return test_media::write_clip(dir / name, c);
}

/// Mean (B, G, R) of the middle of a BGRA float image.
cv::Scalar centre_mean(const cv::Mat& bgra) {
  return cv::mean(bgra(cv::Rect(bgra.cols / 4, bgra.rows / 4, bgra.cols / 2, bgra.rows / 2)));
}

bool is_red(const cv::Scalar& s) {
  return s[2] > 0.8 && s[0] < 0.1;
}
bool is_blue(const cv::Scalar& s) {
  return s[0] > 0.8 && s[2] < 0.1;
}

TEST(StereoPlayGl, EachEyeItsHalfAndKeyFiveSwitchesTheDesktopEye) {
  const fs::path dir = test_files::fresh_dir("app/StereoPlayGl");
  const fs::path clip = red_blue(dir, "tb.mp4");
  auto video = io::VideoSource::open(clip);
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 6; ++k) times.push_back(k * 33'333'333);
  auto input = xr::create_replay_backend(test::still_head_recording(times, 0.0), {});
  const auto sc = test::one_effect_sidecar(effects::EffectType::Exposure, {{0, 0, {0.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = test::small_hidden_loop();
  o.video_layout = {effects::StereoMode::TopBottom, 360};
  o.mirror = xr::MirrorMode::Desktop;
  o.script = [](std::int64_t n) {
    return n == 3 ? std::vector<xr::DesktopEvent>{xr::KeyEvent{xr::Key::Num5, true}}
                  : std::vector<xr::DesktopEvent>{};
  };
  std::vector<cv::Scalar> desktop;
  o.on_frame = [&](xr::Compositor& c, std::int64_t) {
    desktop.push_back(centre_mean(c.read_desktop()));
  };
  FrameLoop loop(o, *input, *video, player);
  loop.run();
  ASSERT_EQ(desktop.size(), 6u);
  for (int n = 1; n < 6; ++n) {
    SCOPED_TRACE(n);
    if (n < 3) {
      EXPECT_TRUE(is_red(desktop[n])) << desktop[n];
    } else if (n > 3) {
      EXPECT_TRUE(is_blue(desktop[n])) << desktop[n];
    }
  }
}

TEST(StereoPlayGl, HeadsetEyesEachSeeTheirHalf) {
  const fs::path dir = test_files::fresh_dir("app/StereoPlayGlEyes");
  const fs::path clip = red_blue(dir, "tb.mp4");
  for (const auto& layout :
       {effects::StereoLayout{effects::StereoMode::TopBottom, 360}, effects::StereoLayout{}}) {
    auto video = io::VideoSource::open(clip);
    std::vector<std::int64_t> times;
    for (std::int64_t k = 0; k < 4; ++k) times.push_back(k * 33'333'333);
    auto input = xr::create_replay_backend(test::still_head_recording(times, 0.0), {});
    const auto sc = test::one_effect_sidecar(effects::EffectType::Exposure, {{0, 0, {0.0}}});
    Player player(sc, video->properties());
    FrameLoopOptions o = test::small_hidden_loop();
    o.video_layout = layout;
    cv::Scalar left, right;
    o.on_frame = [&](xr::Compositor& c, std::int64_t) {
      left = centre_mean(c.read_eye_buffer(0));
      right = centre_mean(c.read_eye_buffer(1));
    };
    FrameLoop loop(o, *input, *video, player);
    loop.run();
    if (layout.stereo()) {
      EXPECT_TRUE(is_red(left)) << left;
      EXPECT_TRUE(is_blue(right)) << right;
    } else {  // mono: both eyes see the same frame (looking at the horizon: its middle rows)
      EXPECT_NEAR(left[0], right[0], 1e-3);
      EXPECT_NEAR(left[2], right[2], 1e-3);
    }
  }
}

}  // namespace
}  // namespace vdfx::app
