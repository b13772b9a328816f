/// @file
/// @brief Autosave on every change, recovery copy removed on a clean exit, kept and offered after
/// a crash (a child process killed without a clean exit).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include "app/editor/autosave.h"
#include "app/editor/editor.h"
#include "editor_test_util.h"

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

}  // namespace
}  // namespace vdfx::app
