/// @file
/// @brief Issue 11, classes 1, 6 and 8 under injected faults: the real vdfx executable with
/// tests/fault/fault_inject.c preloaded, so fsync, rename and write fail as a failing disk would
/// or the process is killed in the middle of a save.
#include <gtest/gtest.h>

#include <filesystem>

#include "command_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;
using test_files::slurp;

/// vdfx with VDFX_FAULT=fault. ASan checks that its runtime comes first among the libraries;
/// a preloaded one comes before it, which is fine here.
CommandResult run_with_fault(const std::string& fault, const std::string& args) {
  return run_vdfx(
      args, "env -u DISPLAY LD_PRELOAD=" + std::string(VDFX_FAULT_SO) + " VDFX_FAULT=" + fault +
                " ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 ");
}

std::size_t temp_files(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) ++n;
  return n;
}

struct Scene {
  fs::path dir;
  std::string render;  //!< `render ... --out ` (the output path follows)
};

Scene setup() {
  Scene s{test_dir(), ""};
  write_test_panorama(s.dir);
  write_text(s.dir / "s.vdfx.json", exposure_sidecar());
  s.render = "render " + (s.dir / "pano.png").string() + " --sidecar " +
             (s.dir / "s.vdfx.json").string() + " --view 0,0 --fov 90 --size 16x8 --out ";
  return s;
}

TEST(Faults, AFailingWriteLeavesTheOldFileAndNoTemporary) {
  const Scene s = setup();
  write_text(s.dir / "out.png", "old");
  for (const char* fault : {"write_enospc", "fsync_file", "rename"}) {
    const CommandResult r = run_with_fault(fault, s.render + (s.dir / "out.png").string());
    EXPECT_EQ(r.exit_code, 1) << fault << "\n" << r.output;
    EXPECT_NE(r.output.find("cannot write " + (s.dir / "out.png").string()), std::string::npos)
        << r.output;
    EXPECT_EQ(slurp(s.dir / "out.png"), "old") << fault;
    EXPECT_EQ(temp_files(s.dir), 0u) << fault;
  }
}

TEST(Faults, AFolderSyncFailureSaysTheFileWasWritten) {
  // Was "cannot write" although the file had already been replaced.
  const Scene s = setup();
  const CommandResult r = run_with_fault("fsync_dir", s.render + (s.dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("out.png: written, but not yet durable"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("cannot write"), std::string::npos) << r.output;
  EXPECT_EQ(cv::imread((s.dir / "out.png").string()).cols, 16);
}

TEST(Faults, TheTemporaryFileOfAKilledSaveIsCleanedUpByTheNextSave) {
  // Killed between writing the temporary file and renaming it: the old file stays, and the
  // temporary file was left forever.
  const Scene s = setup();
  write_text(s.dir / "out.png", "old");
  const CommandResult killed =
      run_with_fault("rename_kill", s.render + (s.dir / "out.png").string());
  EXPECT_NE(killed.exit_code, 0);
  EXPECT_EQ(slurp(s.dir / "out.png"), "old");
  EXPECT_EQ(temp_files(s.dir), 1u);
  const CommandResult again = run_vdfx(s.render + (s.dir / "out.png").string());
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(temp_files(s.dir), 0u);
  EXPECT_EQ(cv::imread((s.dir / "out.png").string()).cols, 16);
}

}  // namespace
}  // namespace vdfx::app::testing
