/// @file
/// @brief Autosave on every change, recovery copy removed on a clean exit, kept and offered after
/// a crash (a child process killed without a clean exit).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include "app/editor/autosave.h"
#include "app/editor/editor.h"
#include "editor_test_util.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

EditorOptions with_autosave(const std::filesystem::path& p) {
  EditorOptions o;
  o.autosave_path = p;
  return o;
}

TEST(EditorAutosave, EveryChangeWritesSidecarAndRecoveryCopyCleanExitRemovesIt) {
  const auto dir = test::temp_dir("autosave_clean");
  const auto path = dir / "clip.vdfx.json";
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, with_autosave(path));
  ed.document().add_keyframe(EffectType::Exposure, {{10.0, 0.0}, 0, {1.0}});
  ASSERT_TRUE(std::filesystem::exists(path));
  ASSERT_TRUE(std::filesystem::exists(recovery_path(path)));
  EXPECT_EQ(io::read_sidecar(path), ed.document().sidecar());
  ed.document().undo();
  EXPECT_TRUE(io::read_sidecar(path).effects.empty());
  EXPECT_NE(ed.autosave_status().find("saved clip.vdfx.json (2 changes)"), std::string::npos);
  EXPECT_TRUE(ed.finish());
  EXPECT_NE(ed.autosave_status().find("(2 changes)"), std::string::npos)
      << "finishing is no change";
  EXPECT_FALSE(std::filesystem::exists(recovery_path(path)));
  EXPECT_FALSE(find_recovery(path).has_value());
}

TEST(EditorAutosave, ASessionWithoutEditsReportsNoChanges) {
  const auto dir = test::temp_dir("autosave_none");
  const auto path = dir / "clip.vdfx.json";
  {
    Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, with_autosave(path));
    EXPECT_TRUE(ed.finish());
    EXPECT_EQ(ed.autosave_status(), "clip.vdfx.json: new sidecar written (no keyframes yet)");
    EXPECT_EQ(io::read_sidecar(path), ed.document().sidecar());
  }
  const auto mtime = std::filesystem::last_write_time(path);
  Editor again(io::read_sidecar(path), DocumentOptions{{.async = false}}, with_autosave(path));
  EXPECT_TRUE(again.finish());
  EXPECT_EQ(again.autosave_status(), "clip.vdfx.json: no changes");
  EXPECT_EQ(std::filesystem::last_write_time(path), mtime) << "an unchanged file is not rewritten";
}

TEST(EditorAutosave, ADragIsSavedOnceWhenItEnds) {
  const auto dir = test::temp_dir("autosave_drag");
  const auto path = dir / "clip.vdfx.json";
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, with_autosave(path));
  ed.document().add_keyframe(EffectType::Exposure, {{10.0, 0.0}, 0, {1.0}});
  ASSERT_EQ(ed.autosave_saves(), 1);
  // A slider drag: one group, a change every frame.
  ed.document().begin_group("drag");
  for (double v : {1.5, 2.0, 2.5, 3.0})
    ed.document().set_keyframe_params(EffectType::Exposure, 0, {v});
  EXPECT_EQ(ed.autosave_saves(), 1) << "nothing written while the drag goes on";
  EXPECT_DOUBLE_EQ(io::read_sidecar(path).effects.at(0).keyframes.at(0).params.at(0), 1.0);
  ed.document().end_group();
  EXPECT_EQ(ed.autosave_saves(), 2) << "one write when it ends";
  EXPECT_EQ(io::read_sidecar(path), ed.document().sidecar());
  // A group without changes writes nothing.
  ed.document().begin_group("nothing");
  ed.document().end_group();
  EXPECT_EQ(ed.autosave_saves(), 2);
  EXPECT_TRUE(ed.finish());
}

TEST(EditorAutosave, CrashLeavesARecoveryCopyThatIsOffered) {
  const auto dir = test::temp_dir("autosave_crash");
  const auto path = dir / "clip.vdfx.json";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, with_autosave(path));
    ed.document().add_keyframe(EffectType::Exposure, {{10.0, 0.0}, 0, {1.0}});
    ed.document().add_keyframe(EffectType::Blur, {{-40.0, 5.0}, 3, {2.0}});
    std::raise(SIGKILL);  // no clean exit
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const auto offer = find_recovery(path);
  ASSERT_TRUE(offer.has_value());
  EXPECT_EQ(offer->path, recovery_path(path));
  EXPECT_NE(offer->message.find("did not exit cleanly"), std::string::npos) << offer->message;
  const io::Sidecar recovered = io::read_sidecar(offer->path);
  ASSERT_EQ(recovered.effects.size(), 2u);
  EXPECT_EQ(recovered.effects[0].type, EffectType::Blur);
  // A recovery copy that differs from the sidecar (the sidecar write failed) says so.
  std::ofstream(path) << "{}";
  EXPECT_NE(find_recovery(path)->message.find("differs"), std::string::npos);
  std::filesystem::remove(path);
  EXPECT_NE(find_recovery(path)->message.find("missing"), std::string::npos);
}

TEST(EditorAutosave, FailureIsReportedNotThrown) {
  Autosave a(std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "editor" / "no_such_dir" / "x" /
             "s.vdfx.json");
  EXPECT_FALSE(a.save(test::empty_sidecar()));
  EXPECT_NE(a.status().find("FAILED"), std::string::npos);
}

TEST(EditorAutosave, AFailedSaveKeepsTheEditsAndIsRetriedUntilOneSucceeds) {
  // Issue 23: a failed autosave said so once and then waited for the next edit. Now the editor
  // keeps the document, says in the status and the heads-up line that it retries, and retries
  // every 2 s of display time until a save succeeds. The failure is real: the folder is gone.
  const auto dir = test::temp_dir("autosave_retry");
  const auto sub = dir / "sub";
  std::filesystem::create_directories(sub);
  const auto path = sub / "clip.vdfx.json";
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, with_autosave(path));
  std::filesystem::remove_all(sub);
  ed.document().add_keyframe(EffectType::Exposure, {{10.0, 0.0}, 0, {1.0}});
  EXPECT_NE(ed.autosave_status().find("autosave FAILED, retrying every 2 s"), std::string::npos)
      << ed.autosave_status();
  EXPECT_NE(ed.autosave_status().find(path.string()), std::string::npos) << ed.autosave_status();
  const xr::InputState in = xr::neutral_input_state(0);
  ed.update(in, 1'000'000'000);
  EXPECT_NE(ed.hud_message().find("autosave FAILED"), std::string::npos) << ed.hud_message();
  ed.update(in, 2'500'000'000);  // not yet 2 s after the first retry's clock started
  EXPECT_FALSE(std::filesystem::exists(path));
  std::filesystem::create_directories(sub);  // the disk has room again
  ed.update(in, 3'100'000'000);
  ASSERT_TRUE(std::filesystem::exists(path)) << ed.autosave_status();
  EXPECT_EQ(io::read_sidecar(path), ed.document().sidecar());
  EXPECT_EQ(ed.autosave_status(), "saved clip.vdfx.json (1 change)");
  EXPECT_EQ(ed.hud_message().find("FAILED"), std::string::npos);
  EXPECT_TRUE(ed.finish());
}

TEST(EditorAutosave, AFileChangedUnderTheEditorIsKeptAndTheAuthorsVersionGoesBesideIt) {
  // Issue 23: another program rewriting the open sidecar was overwritten by the next save.
  const auto dir = test::temp_dir("autosave_changed");
  const auto path = dir / "clip.vdfx.json";
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, with_autosave(path));
  ed.document().add_keyframe(EffectType::Exposure, {{10.0, 0.0}, 0, {1.0}});
  ASSERT_EQ(ed.autosave_saves(), 1);
  // The other program: same size and time would not hide it either (the hash differs).
  io::Sidecar theirs = test::empty_sidecar();
  theirs.interpolation.exponent = 1.5;
  io::write_sidecar(path, theirs);
  ed.document().add_keyframe(EffectType::Exposure, {{-40.0, 0.0}, 0, {-1.0}});
  EXPECT_EQ(io::read_sidecar(path), theirs) << "their version stays";
  std::vector<std::filesystem::path> side;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().rfind("clip-yours-", 0) == 0 &&
        e.path().extension() == ".json")
      side.push_back(e.path());
  ASSERT_EQ(side.size(), 1u);
  EXPECT_EQ(io::read_sidecar(side[0]), ed.document().sidecar()) << "ours, whole, beside it";
  EXPECT_NE(ed.autosave_status().find("clip.vdfx.json was changed by another program"),
            std::string::npos)
      << ed.autosave_status();
  EXPECT_NE(ed.autosave_status().find(side[0].filename().string()), std::string::npos);
  EXPECT_NE(ed.hud_message().find(side[0].filename().string()), std::string::npos);
  // Later edits go to the side file too; the sidecar is never touched again.
  ed.document().undo();
  EXPECT_EQ(io::read_sidecar(side[0]), ed.document().sidecar());
  EXPECT_EQ(io::read_sidecar(path), theirs);
  EXPECT_TRUE(ed.finish());
  EXPECT_EQ(io::read_sidecar(path), theirs);
  EXPECT_FALSE(std::filesystem::exists(recovery_path(side[0])));
  EXPECT_FALSE(std::filesystem::exists(recovery_path(path))) << "nothing left to offer";
}

TEST(EditorAutosave, ARewriteWithTheSameSizeAndTimeIsSeenByItsHash) {
  const auto dir = test::temp_dir("autosave_same_size");
  const auto path = dir / "clip.vdfx.json";
  Autosave a(path);
  io::Sidecar s = test::empty_sidecar();
  ASSERT_TRUE(a.save(s));
  const auto before = fingerprint(path);
  std::string text = test_files::slurp(path);
  const auto digit = text.find_first_of("0123456789", text.find("exponent"));
  ASSERT_NE(digit, std::string::npos);
  text[digit] = text[digit] == '2' ? '3' : '2';  // another value, the same size
  { std::ofstream(path, std::ios::binary) << text; }
  // Back to the old modification time, as a careless tool might leave it.
  const timespec times[2] = {{0, UTIME_OMIT},
                             {static_cast<time_t>(before.mtime_ns / 1'000'000'000),
                              static_cast<long>(before.mtime_ns % 1'000'000'000)}};
  ASSERT_EQ(::utimensat(AT_FDCWD, path.c_str(), times, 0), 0);
  EXPECT_EQ(fingerprint(path).size, before.size);
  EXPECT_EQ(fingerprint(path).mtime_ns, before.mtime_ns);
  EXPECT_NE(fingerprint(path).hash, before.hash);
  ASSERT_TRUE(a.save(s));
  EXPECT_TRUE(a.diverted_to().has_value());
  EXPECT_EQ(test_files::slurp(path), text);
}

TEST(EditorAutosave, AReadOnlySessionWritesACopyOnlyWhenSomethingChanged) {
  const auto dir = test::temp_dir("autosave_copy");
  const auto copy = dir / "clip-copy-x.vdfx.json";
  {
    Autosave a(copy, Autosave::Target::CopyWhenChanged);
    EXPECT_TRUE(a.finish(test::empty_sidecar()));
    EXPECT_FALSE(std::filesystem::exists(copy)) << "no change, no copy";
  }
  EditorOptions o = with_autosave(copy);
  o.read_only_note = "open in vdfx edit (process 1 on h); edits are saved to clip-copy-x.vdfx.json";
  Editor ed(test::empty_sidecar(), DocumentOptions{{.async = false}}, o);
  ed.update(xr::neutral_input_state(0), 0);
  EXPECT_EQ(ed.hud_text().rfind("READ-ONLY", 0), 0u) << ed.hud_text();
  EXPECT_EQ(ed.status_text().rfind("READ-ONLY: open in vdfx edit", 0), 0u) << ed.status_text();
  EXPECT_NE(ed.hud_message().find("edits are saved to clip-copy-x"), std::string::npos);
  ed.document().add_keyframe(EffectType::Exposure, {{10.0, 0.0}, 0, {1.0}});
  EXPECT_EQ(io::read_sidecar(copy), ed.document().sidecar());
  EXPECT_TRUE(ed.finish());
}

TEST(EditorAutosave, SideFilesKeepTheSidecarsFolderAndExtension) {
  EXPECT_EQ(side_file_path("/a/clip.vdfx.json", "yours-1"), "/a/clip-yours-1.vdfx.json");
  EXPECT_EQ(side_file_path("b/notes.json", "copy-2"), "b/notes-copy-2.json");
}

}  // namespace
}  // namespace vdfx::app
