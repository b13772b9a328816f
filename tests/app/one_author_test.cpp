/// @file
/// @brief Issue 23 through the real executable: a sidecar another editor has open (its lock held
/// by a second real process) is never written by `replay --sidecar-out`, `export` or `edit
/// --access write` (exit 1 naming the owner), a stale lock is not in the way; and every writer
/// onto a full disk (ENOSPC injected by tests/fault/fault_inject.c) ends with exit 1 naming the
/// file and the system's reason, leaving nothing half-written.
#include <gtest/gtest.h>

#include <filesystem>

#include "command_test_util.h"
#include "export_test_util.h"
#include "tests/lock_holder.h"
#include "tests/support/test_paths.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;
using test_files::LockHolder;
using test_files::slurp;

/// vdfx whose writes to regular files fail with ENOSPC after `after` bytes. `timeout` comes
/// first: the injector is preloaded into vdfx only (in the sanitized build it needs the
/// sanitizers' runtime, which `timeout` does not have).
CommandResult run_on_full_disk(const std::string& args, long after = 0) {
  return run_vdfx(args,
                  "timeout 120 env -u DISPLAY LD_PRELOAD=" + std::string(VDFX_FAULT_SO) +
                      " VDFX_FAULT=write_enospc VDFX_FAULT_AFTER=" + std::to_string(after) +
                      " ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 ");
}

std::size_t files_in(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(OneAuthor, ReplayNeverWritesASidecarAnotherEditorHasOpen) {
  const fs::path dir = panorama_and_sidecar();
  write_short_recording(dir / "rec.vdrec.jsonl");
  const fs::path out = dir / "out.vdfx.json";
  write_text(out, "the other author's work");
  const std::string args = "replay " + (dir / "rec.vdrec.jsonl").string() + " --video " +
                           (dir / "pano.png").string() + " --sidecar-out " + out.string();
  {
    LockHolder editor(out);
    const CommandResult r = run_vdfx_headless(args);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("refusing to write --sidecar-out " + out.string() +
                            ": it is open in vdfx edit (process " + std::to_string(editor.pid())),
              std::string::npos)
        << r.output;
    EXPECT_EQ(slurp(out), "the other author's work");
    // Reading it is fine: the same sidecar as --sidecar-in, written elsewhere.
    const CommandResult read = run_vdfx_headless(
        "replay " + (dir / "rec.vdrec.jsonl").string() + " --video " + (dir / "pano.png").string() +
        " --sidecar-in " + (dir / "s.vdfx.json").string() + " --sidecar-out " +
        (dir / "elsewhere.vdfx.json").string());
    EXPECT_EQ(read.exit_code, 0) << read.output;
  }
  // The editor is gone (killed: its lock is left behind, stale): no longer in the way. The file
  // is not a sidecar, so only --force replaces it (tests/app/sidecar_out_test.cpp).
  ASSERT_TRUE(fs::exists(dir / "out.vdfx.json.lock"));
  const CommandResult after = run_vdfx_headless(args + " --force");
  EXPECT_EQ(after.exit_code, 0) << after.output;
  EXPECT_NE(slurp(out), "the other author's work");
}

TEST(OneAuthor, EditAskedToWriteALockedSidecarExitsOneBeforeAnyWindow) {
  const fs::path dir = panorama_and_sidecar();
  const fs::path sidecar = dir / "s.vdfx.json";
  const std::string before = slurp(sidecar);
  LockHolder editor(sidecar);
  const CommandResult r =
      run_vdfx_headless("edit --sidecar " + sidecar.string() + " --access write --hidden");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(sidecar.string() + " is open in vdfx edit (process " +
                          std::to_string(editor.pid())),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--access read-only"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(sidecar), before);
  EXPECT_NE(slurp(dir / "s.vdfx.json.lock").find(std::to_string(editor.pid())), std::string::npos)
      << "the owner's lock is left alone";
}

TEST(OneAuthor, ExportNeverReplacesAFileAnotherEditorHasOpen) {
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "out.mp4";
  write_text(out, "old");
  LockHolder editor(out, "vdfx edit");
  const CommandResult r = run_vdfx("export " + f.clip.string() + " --sidecar " +
                                   f.sidecar.string() + " --baked " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("it is open in vdfx edit (process " + std::to_string(editor.pid())),
            std::string::npos)
      << r.output;
  EXPECT_EQ(slurp(out), "old");
  // The sidecar it reads may be open in an editor: reading is fine.
  LockHolder reader(f.sidecar);
  const CommandResult ok = run_vdfx("export " + f.clip.string() + " --sidecar " +
                                    f.sidecar.string() + " --baked " + (f.dir / "b.mp4").string());
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST(OneAuthor, AnExportOntoAFullDiskIsExitOneNamingOutAndTheReason) {
  // Was exit 3 "internal error: VideoEncoder: writing video failed: No space left on device".
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "full.mp4";
  for (const long after : {0L, 20000L}) {  // at the header, and in the middle of the frames
    const std::size_t before = files_in(f.dir);
    const CommandResult r = run_on_full_disk("export " + f.clip.string() + " --sidecar " +
                                                 f.sidecar.string() + " --baked " + out.string(),
                                             after);
    EXPECT_EQ(r.exit_code, 1) << after << "\n" << r.output;
    EXPECT_NE(r.output.find(out.string() + ": cannot write the"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(files_in(f.dir), before) << "the partial file is removed";
  }
}

TEST(OneAuthor, ReplayFramesAndBenchOntoAFullDiskAreExitOneNamingTheFile) {
  const fs::path dir = panorama_and_sidecar();
  write_short_recording(dir / "rec.vdrec.jsonl");
  const CommandResult frames = run_on_full_disk(
      "replay " + (dir / "rec.vdrec.jsonl").string() + " --video " + (dir / "pano.png").string() +
      " --sidecar-out " + (dir / "o.vdfx.json").string() + " --frames " + (dir / "f").string());
  EXPECT_EQ(frames.exit_code, 1) << frames.output;
  EXPECT_NE(frames.output.find("cannot write " + (dir / "f").string() + "/replay_000.png"),
            std::string::npos)
      << frames.output;
  EXPECT_NE(frames.output.find("No space left on device"), std::string::npos) << frames.output;

  const std::string bench = "bench --quick --filter '^rbf\\.solve/N=10$' ";
  const CommandResult json = run_on_full_disk(bench + "--json " + (dir / "r.json").string());
  EXPECT_EQ(json.exit_code, 1) << json.output;
  EXPECT_NE(json.output.find("cannot write " + (dir / "r.json").string()), std::string::npos)
      << json.output;
  EXPECT_NE(json.output.find("No space left on device"), std::string::npos) << json.output;
  EXPECT_FALSE(fs::exists(dir / "r.json"));

  const CommandResult plot = run_on_full_disk(bench + "--plot " + (dir / "plots").string());
  EXPECT_EQ(plot.exit_code, 1) << plot.output;
  EXPECT_NE(plot.output.find("No space left on device"), std::string::npos) << plot.output;
  EXPECT_EQ(plot.output.find("internal error"), std::string::npos) << plot.output;
}

}  // namespace
}  // namespace vdfx::app::testing
