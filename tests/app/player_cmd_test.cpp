/// @file
/// @brief `vdfx play` / `vdfx edit` command-line checks that need no window: bad input is exit 1
/// with a message saying what, --help documents the keys.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "command_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

using CmdResult = testing::CommandResult;

CmdResult run(const std::string& args) {
  // DISPLAY is unset so a command that got as far as opening a window would fail differently.
  return testing::run_vdfx(args, "env -u DISPLAY -u WAYLAND_DISPLAY ");
}

const std::string kDemo = std::string(VDFX_SOURCE_DIR) + "/app/demo/interior.vdfx.json";
const std::string kStill = "/usr/share/blender/datafiles/studiolights/world/sunrise.exr";

TEST(PlayerCmd, BadInputIsExitOneWithAClearMessage) {
  const struct {
    std::string args;
    std::string says;
  } rows[] = {
      {"play /nonexistent/clip.mp4 --sidecar " + kDemo, "/nonexistent/clip.mp4"},
      {"play " + kStill + " --sidecar " + kDemo + " --hmd no-such-headset", "no-such-headset"},
      {"play " + kStill + " --sidecar /nonexistent/fx.vdfx.json", "/nonexistent/fx.vdfx.json"},
      {"play " + kStill + " --sidecar " + kDemo + " --input replay:/nonexistent/r.vdrec.jsonl",
       "/nonexistent/r.vdrec.jsonl"},
      {"edit /nonexistent/clip.mp4", "/nonexistent/clip.mp4"},
      {"edit --hmd /nonexistent/h.json", "/nonexistent/h.json"},
  };
  for (const auto& r : rows) {
    const CmdResult out = run(r.args);
    EXPECT_EQ(out.exit_code, 1) << r.args << "\n" << out.output;
    EXPECT_NE(out.output.find(r.says), std::string::npos) << r.args << "\n" << out.output;
  }
}

TEST(PlayerCmd, UsageErrorsAreExitTwo) {
  for (const std::string& args : std::vector<std::string>{
           "play", "play " + kStill, "play " + kStill + " --sidecar " + kDemo + " --scale 0",
           "play " + kStill + " --sidecar " + kDemo + " --window 12",
           "play " + kStill + " --sidecar " + kDemo + " --mirror sideways"}) {
    const CmdResult out = run(args);
    EXPECT_EQ(out.exit_code, 2) << args << "\n" << out.output;
  }
}

TEST(PlayerCmd, HelpListsEveryKeyAndTheSimBindings) {
  const CmdResult out = run("play --help");
  EXPECT_EQ(out.exit_code, 0);
  for (const char* s :
       {"pause / play", "per-pixel", "unaltered", "desktop view", "pre-distorted panels",
        "through the lens", "left eye, undistorted", "Escape", "--fov", "--mirror",
        "/user/hand/right/input/trigger/value", "turn the head", "--stats", "--screenshot",
        "--frames", "--record", "--scale"})
    EXPECT_NE(out.output.find(s), std::string::npos) << s;
}

}  // namespace
}  // namespace vdfx::app
