/// @file
/// @brief `vdfx play` end to end under Xvfb: a replayed session on the demo still, the
/// screenshot, --record and --stats.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "command_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

using CmdResult = testing::CommandResult;

CmdResult run(const std::string& args) {
  return testing::run_vdfx(args);
}

TEST(PlayerCmdGl, ReplayedDemoWritesScreenshotRecordingAndStats) {
  const std::filesystem::path dir = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "player_cmd";
  std::filesystem::create_directories(dir);
  const auto png = dir / "mirror.png", rec = dir / "again.vdrec.jsonl";
  std::filesystem::remove(png);
  std::filesystem::remove(rec);
  const std::string src = VDFX_SOURCE_DIR;
  const CmdResult out =
      run("play /usr/share/blender/datafiles/studiolights/world/interior.exr --sidecar " + src +
          "/app/demo/interior.vdfx.json --input replay:" + src +
          "/recordings/sim_look_and_place.vdrec.jsonl --frames 4 --scale 0.05 "
          "--window 200x100 --mirror pre --hidden --stats --screenshot " +
          png.string() + " --record " + rec.string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  const cv::Mat m = cv::imread(png.string());
  ASSERT_FALSE(m.empty());
  EXPECT_EQ(m.cols, 200);
  EXPECT_EQ(m.rows, 100);
  double lo = 0, hi = 0;
  cv::minMaxLoc(m.reshape(1), &lo, &hi);
  EXPECT_GT(hi, 20.0);  // something is drawn
  // The recording decorator wrote the header and one sample per frame.
  std::ifstream in(rec);
  int lines = 0;
  for (std::string l; std::getline(in, l);) ++lines;
  EXPECT_EQ(lines, 1 + 4);
  // --stats: medians of the GPU stages at exit.
  for (const char* s : {"gpu video", "gpu effects", "gpu distortion", "medians over 4 frames"})
    EXPECT_NE(out.output.find(s), std::string::npos) << s << "\n" << out.output;
}

}  // namespace
}  // namespace vdfx::app
