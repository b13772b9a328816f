/// @file
/// @brief `vdfx play` and `vdfx edit` take a baked export like any video (under Xvfb).
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "export_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

TEST(ExportPlayGl, PlayAndEditAcceptTheBakedExport) {
  const testing::Fixture f = testing::make_fixture();
  const fs::path out = f.dir / "baked.mp4";
  const auto e = testing::run_vdfx("export " + f.clip.string() + " --sidecar " +
                                   f.sidecar.string() + " --baked " + out.string());
  ASSERT_EQ(e.exit_code, 0) << e.output;
  const std::string rec =
      std::string(VDFX_SOURCE_DIR) + "/recordings/sim_look_and_place.vdrec.jsonl";
  const std::string window = " --input replay:" + rec +
                             " --frames 4 --scale 0.05 --window 160x80 --hidden"
                             " --decode-timeout 5000 --screenshot ";
  const fs::path play_png = f.dir / "play.png", edit_png = f.dir / "edit.png";
  const auto p = testing::run_vdfx("play " + out.string() + " --sidecar " + f.sidecar.string() +
                                   window + play_png.string());
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const fs::path copy = f.dir / "edit.vdfx.json";
  fs::copy_file(f.sidecar, copy);
  const auto ed = testing::run_vdfx("edit " + out.string() + " --sidecar " + copy.string() +
                                    window + edit_png.string());
  ASSERT_EQ(ed.exit_code, 0) << ed.output;
  for (const fs::path& png : {play_png, edit_png}) {
    const cv::Mat m = cv::imread(png.string());
    ASSERT_FALSE(m.empty()) << png;
    double hi = 0;
    cv::minMaxLoc(m.reshape(1), nullptr, &hi);
    EXPECT_GT(hi, 40.0) << png << ": the video is drawn";
  }
}

}  // namespace
}  // namespace vdfx::app
