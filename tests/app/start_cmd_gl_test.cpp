/// @file
/// @brief Never a failed start: `vdfx play` and `vdfx edit` started again and again on a 4K
/// long-GOP H.264 clip (one keyframe: the first frame takes longest to decode) all open, run and
/// exit cleanly. Before the loading state, about one start in three to seven failed with
/// "VideoLayerGl::render: no frame uploaded" (the first frame rendered before the first decode).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "command_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx;

/// A 3840 x 1920, 30-frame H.264 clip with a single keyframe, made with FFmpeg (CI installs it).
fs::path long_gop_clip() {
  const fs::path clip = fs::path(VDFX_TEST_OUTPUT_DIR) / "start" / "long_gop_4k.mp4";
  if (fs::exists(clip)) return clip;
  fs::create_directories(clip.parent_path());
  const std::string cmd =
      "ffmpeg -y -loglevel error -f lavfi -i testsrc2=size=3840x1920:rate=30 -frames:v 30 "
      "-c:v libx264 -preset ultrafast -g 300 -bf 3 -pix_fmt yuv420p " +
      clip.string();
  EXPECT_EQ(std::system(cmd.c_str()), 0) << "ffmpeg is needed to make the test clip: " << cmd;
  return clip;
}

TEST(StartCmdGl, PlayAndEditStartEveryTimeOnALongGopClip) {
  const fs::path clip = long_gop_clip();
  ASSERT_TRUE(fs::exists(clip));
  const fs::path dir = testing::test_dir();
  const fs::path sidecar = dir / "clip.vdfx.json";
  int failures = 0;
  for (int i = 0; i < 4; ++i) {
    for (const char* cmd : {"play", "edit"}) {
      fs::remove(sidecar);
      fs::remove(fs::path(sidecar.string() + ".autosave"));
      if (std::string(cmd) == "play") {
        // play needs a sidecar: an empty one for the clip
        run_vdfx("edit " + clip.string() + " --sidecar " + sidecar.string() +
                 " --frames 1 --hidden");
      }
      const auto r = run_vdfx(std::string(cmd) + " " + clip.string() + " --sidecar " +
                              sidecar.string() + " --frames 4 --hidden --no-vsync");
      if (r.exit_code != 0) {
        ++failures;
        ADD_FAILURE() << cmd << " start " << i << " exit " << r.exit_code << ":\n" << r.output;
      }
    }
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace vdfx::app
