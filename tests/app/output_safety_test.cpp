/// @file
/// @brief Issue 11, class 1 (data loss through output paths), through the real executable: an
/// output that is one of the command's inputs is refused (exit 1, the input intact) whatever its
/// name; a named link is written through and kept; pipes and devices are refused without
/// blocking; links inside a --frames folder are refused.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "command_test_util.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;
using test_files::slurp;

CommandResult run(const std::string& args) {
  return run_vdfx_headless(args);
}

/// pano.png, s.vdfx.json and a two-line recording rec.vdrec.jsonl in a fresh folder.
fs::path setup() {
  const fs::path dir = panorama_and_sidecar();
  write_short_recording(dir / "rec.vdrec.jsonl");
  return dir;
}

std::string render_args(const fs::path& dir) {
  return "render " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
         " --view 0,0 --fov 90 --size 32x16 --out ";
}

TEST(OutputSafety, RenderRefusesAnOutputThatIsOneOfItsInputs) {
  const fs::path dir = setup();
  fs::create_hard_link(dir / "pano.png", dir / "hard.png");
  fs::create_symlink("s.vdfx.json", dir / "soft.json");
  const std::string pano = slurp(dir / "pano.png"), sidecar = slurp(dir / "s.vdfx.json");
  const struct {
    fs::path out;
    const char* says;
  } rows[] = {
      {dir / "s.vdfx.json", "it is the --sidecar input"},
      {dir / "pano.png", "it is the INPUT input"},
      {dir / "." / "pano.png", "it is the INPUT input"},
      {dir / "hard.png", "the same file as the INPUT input"},
      {dir / "soft.json", "the same file as the --sidecar input"},
  };
  for (const auto& row : rows) {
    const CommandResult r = run(render_args(dir) + row.out.string());
    EXPECT_EQ(r.exit_code, 1) << row.out << "\n" << r.output;
    EXPECT_NE(r.output.find(row.says), std::string::npos) << r.output;
  }
  EXPECT_EQ(slurp(dir / "pano.png"), pano);
  EXPECT_EQ(slurp(dir / "s.vdfx.json"), sidecar);
}

TEST(OutputSafety, ReplayRefusesASidecarOutThatIsOneOfItsInputs) {
  const fs::path dir = setup();
  const std::string rec = slurp(dir / "rec.vdrec.jsonl"), pano = slurp(dir / "pano.png");
  const std::string base = "replay " + (dir / "rec.vdrec.jsonl").string() + " --video " +
                           (dir / "pano.png").string() + " --sidecar-in " +
                           (dir / "s.vdfx.json").string() + " --sidecar-out ";
  // (--sidecar-in itself may be --sidecar-out: a sidecar is updated in place, atomically;
  // tests/app/sidecar_out_test.cpp.)
  for (const char* name : {"rec.vdrec.jsonl", "pano.png"}) {
    const CommandResult r = run(base + (dir / name).string());
    EXPECT_EQ(r.exit_code, 1) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("refusing to write --sidecar-out"), std::string::npos) << r.output;
  }
  EXPECT_EQ(slurp(dir / "rec.vdrec.jsonl"), rec);
  EXPECT_EQ(slurp(dir / "pano.png"), pano);
}

TEST(OutputSafety, ANamedLinkIsWrittenThroughAndKept) {
  const fs::path dir = setup();
  fs::create_directories(dir / "renders");
  write_text(dir / "renders" / "view.png", "old");
  fs::create_symlink("renders/view.png", dir / "latest.png");
  const CommandResult r = run(render_args(dir) + (dir / "latest.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(dir / "latest.png"));
  const cv::Mat img = cv::imread((dir / "renders" / "view.png").string());
  EXPECT_EQ(img.cols, 32);
  EXPECT_EQ(img.rows, 16);
}

TEST(OutputSafety, PipesAndDevicesAreRefusedWithoutBlocking) {
  const fs::path dir = setup();
  ASSERT_EQ(::mkfifo((dir / "pipe.png").c_str(), 0600), 0);
  // No reader ever opens the pipe: writing it would block (the time limit would end it, 124).
  const CommandResult r = run(render_args(dir) + (dir / "pipe.png").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("named pipe"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_fifo(dir / "pipe.png"));
  // A link to a device (a link, so that nothing here can ever replace a real device node).
  fs::create_symlink("/dev/null", dir / "null.png");
  const CommandResult d = run(render_args(dir) + (dir / "null.png").string());
  EXPECT_EQ(d.exit_code, 1) << d.output;
  EXPECT_NE(d.output.find("character device"), std::string::npos) << d.output;
  EXPECT_TRUE(fs::is_symlink(dir / "null.png"));
}

TEST(OutputSafety, ReplayFramesNeverFollowALinkInTheFolder) {
  const fs::path dir = setup();
  const std::string sidecar = slurp(dir / "s.vdfx.json");
  fs::create_directories(dir / "frames");
  fs::create_symlink("../s.vdfx.json", dir / "frames" / "replay_000.png");
  const CommandResult r =
      run("replay " + (dir / "rec.vdrec.jsonl").string() + " --video " +
          (dir / "pano.png").string() + " --sidecar-out " + (dir / "out.vdfx.json").string() +
          " --frames " + (dir / "frames").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("replay_000.png: it is a symbolic link"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(dir / "s.vdfx.json"), sidecar);
}

TEST(OutputSafety, RecordAndScreenshotRefuseTheCommandsInputs) {
  const fs::path dir = setup();
  const std::string sidecar = slurp(dir / "s.vdfx.json"), rec = slurp(dir / "rec.vdrec.jsonl");
  const std::string play = "play " + (dir / "pano.png").string() + " --sidecar " +
                           (dir / "s.vdfx.json").string() +
                           " --input replay:" + (dir / "rec.vdrec.jsonl").string();
  const struct {
    std::string args;
    const char* says;
  } rows[] = {
      {play + " --record " + (dir / "s.vdfx.json").string(), "--record"},
      {play + " --record " + (dir / "rec.vdrec.jsonl").string(), "--input replay: input"},
      {play + " --screenshot " + (dir / "pano.png").string(), "VIDEO input"},
      {"edit " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
           " --recover no --record " + (dir / "s.vdfx.json").string(),
       "--sidecar input"},
  };
  // Refused before any window opens: exit 1 even without a display.
  for (const auto& row : rows) {
    const CommandResult r = run(row.args);
    EXPECT_EQ(r.exit_code, 1) << row.args << "\n" << r.output;
    EXPECT_NE(r.output.find(row.says), std::string::npos) << r.output;
  }
  EXPECT_EQ(slurp(dir / "s.vdfx.json"), sidecar);
  EXPECT_EQ(slurp(dir / "rec.vdrec.jsonl"), rec);
}

}  // namespace
}  // namespace vdfx::app::testing
