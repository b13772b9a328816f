/// @file
/// @brief `vdfx replay` and `vdfx suggest` on stereo video (docs/stereo.md): --layout taken, the
/// layout recorded in the sidecar written, the left eye's image analysed and shown (VR180
/// suggestions: tests/app/suggest_test.cpp, SuggestVr180.*).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "command_test_util.h"
#include "io/sidecar.h"
#include "tests/media_clips.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx;
using testing::test_dir;

/// Top-bottom: the left eye red, the right eye blue (RGB), 128 x 128, 30 frames.
fs::path red_blue(const fs::path& dir) {
  cv::Mat frame(128, 128, CV_8UC3, cv::Scalar(220, 0, 0));
  frame.rowRange(64, 128).setTo(cv::Scalar(0, 0, 220));
  test_media::ClipSpec c;
  c.width = c.height = 128;
  c.frames = 30;
  c.frame = [frame](int) { return frame; };
  return test_media::write_clip(dir / "tb.mp4", c);
}

TEST(StereoCommands, ReplayRecordsTheLayoutAndShowsTheLeftEye) {
  const fs::path dir = test_dir();
  const fs::path clip = red_blue(dir);
  const fs::path rec = dir / "r.vdrec.jsonl";
  testing::write_short_recording(rec);
  const fs::path out = dir / "out.vdfx.json";
  const testing::CommandResult r =
      run_vdfx("replay " + rec.string() + " --video " + clip.string() + " --sidecar-out " +
               out.string() + " --layout top-bottom --frames " + (dir / "frames").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(io::read_sidecar(out).video.stereo(),
            (effects::StereoLayout{effects::StereoMode::TopBottom, 360}));
  int shown = 0;
  for (const auto& e : fs::directory_iterator(dir / "frames")) {
    const cv::Mat bgr = cv::imread(e.path().string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(bgr.empty());
    // The video around the centre (panels may cover other parts): red, no blue.
    const cv::Scalar m = cv::mean(bgr(cv::Rect(bgr.cols / 2 - 20, bgr.rows / 2 - 20, 40, 40)));
    EXPECT_GT(m[2], 150.0) << e.path();
    EXPECT_LT(m[0], 40.0) << e.path();
    ++shown;
  }
  EXPECT_GT(shown, 0);
}

TEST(StereoCommands, SuggestAnalysesTheLeftEyeAndRecordsTheCoverage) {
  const fs::path dir = test_dir();
  const fs::path clip = red_blue(dir);
  const fs::path out = dir / "out.vdfx.json";
  testing::CommandResult r = run_vdfx("suggest exposure " + clip.string() + " --sidecar-out " +
                                      out.string() + " --layout top-bottom");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(io::read_sidecar(out).video.stereo().mode, effects::StereoMode::TopBottom);
  r = run_vdfx("suggest exposure " + clip.string() + " --sidecar-out " +
               (dir / "vr.vdfx.json").string() + " --layout top-bottom --coverage 180");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(io::read_sidecar(dir / "vr.vdfx.json").video.stereo(),
            (effects::StereoLayout{effects::StereoMode::TopBottom, 180}));
}

}  // namespace
}  // namespace vdfx::app
