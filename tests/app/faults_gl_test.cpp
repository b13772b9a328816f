/// @file
/// @brief Issue 11, class 6 in the window loop: `play --record` onto a disk that fills up was
/// exit 3 ("internal error"); it is exit 1 naming the recording, and the recording keeps its
/// whole lines (tests/fault/fault_inject.c makes writes fail with ENOSPC after 2000 bytes).
#include <gtest/gtest.h>

#include <filesystem>

#include "command_test_util.h"
#include "io/recording.h"
#include "tests/support/test_paths.h"

namespace vdfx::app::testing {
namespace {

TEST(FaultsGl, PlayRecordOntoAFullDiskIsAnInputErrorAndKeepsWholeLines) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const auto rec = dir / "rec.vdrec.jsonl";
  // Mesa's shader cache would write files of its own and use up the 2000 bytes.
  const CommandResult r = run_vdfx(
      "play " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
          " --input replay:" +
          (test_files::recordings_dir() / "sim_look_and_place.vdrec.jsonl").string() +
          " --record " + rec.string() + " --hidden --scale 0.05 --window 64x32 --frames 30",
      "env MESA_SHADER_CACHE_DISABLE=true LD_PRELOAD=" + std::string(VDFX_FAULT_SO) +
          " VDFX_FAULT=write_enospc VDFX_FAULT_AFTER=2000"
          " ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 ");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(rec.string() + ": cannot write the recording (No space left on device)"),
            std::string::npos)
      << r.output;
  const io::Recording back = io::read_recording(rec);
  EXPECT_GT(back.lines.size(), 0u);
  EXPECT_TRUE(back.warnings.empty());  // no partial line was left behind
}

}  // namespace
}  // namespace vdfx::app::testing
