/// @file
/// @brief The anchor tests' turning clip on disk (app/bench/turning_clip.h): the demo room's
/// panorama turned 45 degrees a frame (32 columns of 256: an exact shift) over 8 frames at 8 fps,
/// and three sidecars for it: the window's exposure anchored to the world, the same fixed in the
/// picture (the video anchor), and none (the unaltered film). Written once per test process.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/bench/turning_clip.h"
#include "io/sidecar.h"
#include "tests/test_files.h"

namespace vdfx::app::testing {

inline constexpr int kTurnFrames = 8, kTurnWidth = 256;
inline constexpr double kTurnDeg = 360.0;

struct TurningClipFiles {
  std::filesystem::path dir, video, anchored, fixed, plain;
};

inline const TurningClipFiles& turning_clip_files() {
  static const TurningClipFiles c = [] {
    TurningClipFiles c;
    // A folder per test: ctest runs each test in its own process, several at once, and each
    // process writes the clip once.
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    c.dir = test_files::fresh_dir("app/TurningClip/" + std::string(test->test_suite_name()) + "." +
                                  test->name());
    c.video = c.dir / "turn.mp4";
    bench::write_turning_clip(c.video, bench::interior_panorama(kTurnWidth), kTurnFrames, kTurnDeg,
                              8);
    const io::VideoInfo video{"turn.mp4", 8.0, kTurnFrames, kTurnWidth, kTurnWidth / 2};
    const effects::CameraMotion camera = bench::turning_camera(kTurnFrames, kTurnDeg);
    c.anchored = c.dir / "world.vdfx.json";
    c.fixed = c.dir / "video.vdfx.json";
    c.plain = c.dir / "plain.vdfx.json";
    io::write_sidecar(c.anchored,
                      bench::turning_sidecar(video, camera, {effects::Anchor::Kind::World, {}}));
    io::write_sidecar(c.fixed, bench::turning_sidecar(video, camera, {}));
    io::Sidecar plain = bench::turning_sidecar(video, camera, {});
    plain.effects.clear();
    io::write_sidecar(c.plain, plain);
    return c;
  }();
  return c;
}

/// Where the window is in the video frame at frame f of the turning clip.
inline effects::Direction turning_window_at(std::int64_t f) {
  return bench::video_direction(bench::kRoomWindow,
                                bench::turning_yaw_deg(static_cast<int>(f), kTurnFrames, kTurnDeg));
}

/// The exposure an image applied against another of the same view: log2 of their sums' ratio.
inline double applied_stops(const cv::Mat& with, const cv::Mat& without) {
  const cv::Scalar a = cv::sum(with), b = cv::sum(without);
  return std::log2((a[0] + a[1] + a[2]) / (b[0] + b[1] + b[2]));
}

}  // namespace vdfx::app::testing
