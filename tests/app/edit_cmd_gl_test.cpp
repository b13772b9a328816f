/// @file
/// @brief `vdfx edit` end to end under Xvfb: a recorded editing session replayed in the window
/// leaves the same keyframes as `vdfx replay`, and the window shows the panels over the effects
/// (golden screenshot of the desktop view at the default window size, compared at half size).
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "command_test_util.h"
#include "io/file_lock.h"
#include "io/sidecar.h"
#include "tests/golden_bgr.h"
#include "tests/lock_holder.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx;

const std::string kSrc = VDFX_SOURCE_DIR;
const std::string kSunrise = "/usr/share/blender/datafiles/studiolights/world/sunrise.exr";
const std::string kRecording = kSrc + "/recordings/editor_place_exposure.vdrec.jsonl";
// The desktop view a sim session opens in (the recording's header: 1280 x 720, 100 degrees).
const std::string kMirror = " --hidden --window 1280x720";

TEST(EditCmdGl, ReplayedSessionWritesTheReplaysKeyframesAndShowsPanels) {
  const fs::path dir = testing::test_dir();
  const fs::path sidecar = dir / "new.vdfx.json", reference = dir / "reference.vdfx.json";
  const fs::path png = dir / "editor.png", plain = dir / "plain.png";

  // The headless replay's answer.
  const auto ref = run_vdfx("replay " + kRecording + " --video " + kSunrise + " --sidecar-out " +
                            reference.string());
  ASSERT_EQ(ref.exit_code, 0) << ref.output;

  // The window: a sidecar that does not exist yet is created for the video.
  const auto out =
      run_vdfx("edit " + kSunrise + " --sidecar " + sidecar.string() +
               " --input replay:" + kRecording + kMirror + " --screenshot " + png.string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("new sidecar"), std::string::npos) << out.output;
  ASSERT_TRUE(fs::exists(sidecar)) << out.output;
  EXPECT_FALSE(fs::exists(fs::path(sidecar.string() + ".autosave")))
      << "a clean exit removes the recovery copy";
  const io::Sidecar got = io::read_sidecar(sidecar), want = io::read_sidecar(reference);
  ASSERT_EQ(got.effects.size(), 1u);
  EXPECT_EQ(got.effects, want.effects);

  // The same view without the panels: the played sidecar in `vdfx play`, same input and mirror.
  const auto p =
      run_vdfx("play " + kSunrise + " --sidecar " + sidecar.string() +
               " --input replay:" + kRecording + kMirror + " --screenshot " + plain.string());
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const cv::Mat a = cv::imread(png.string()), b = cv::imread(plain.string());
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  // The panels cover part of the view: there the images differ; elsewhere they agree.
  cv::Mat diff, grey;
  cv::absdiff(a, b, diff);
  cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
  const double changed = cv::countNonZero(grey > 24) / static_cast<double>(grey.total());
  EXPECT_GT(changed, 0.05) << "panels cover part of the view";
  // (About 0.80 with the views panel's tracking rows: a whole-window cover would be 1.)
  EXPECT_LT(changed, 0.85) << "the video stays visible around the panels";
  // Text: bright, near-white pixels on the dark panels, where the plain view has none.
  // Text and highlights: light grey pixels on the dark panels (small at this size, so a low bar).
  cv::Mat textish;
  cv::inRange(a, cv::Scalar(110, 110, 110), cv::Scalar(255, 255, 255), textish);
  EXPECT_GE(cv::countNonZero(textish & (grey > 24)), 20) << "light text pixels on the panels";

  cv::Mat half;
  cv::resize(a, half, {a.cols / 2, a.rows / 2}, 0, 0, cv::INTER_AREA);
  const std::string g =
      test_images::compare_with_golden(half, "app", "edit_desktop_view", 48.0, 1.5);
  EXPECT_TRUE(g.empty()) << g;
}

TEST(EditCmdGl, DemoRecordingOnTheBundledDemoCopy) {
  const fs::path dir = testing::test_dir();
  const fs::path copy = dir / "demo.vdfx.json";
  fs::copy_file(kSrc + "/app/demo/interior.vdfx.json", copy);
  const std::size_t before = io::read_sidecar(copy).effects.size();
  const auto out =
      run_vdfx("edit --sidecar " + copy.string() + " --input replay:" + kSrc +
               "/recordings/demo.vdrec.jsonl --frames 60 --hidden --scale 0.1 --window 160x90");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  const io::Sidecar s = io::read_sidecar(copy);
  EXPECT_GE(s.effects.size(), before);
  EXPECT_FALSE(fs::exists(fs::path(copy.string() + ".autosave"))) << "clean exit";
}

TEST(EditCmdGl, RecoveryCopyIsOfferedAndDeclinedByDefault) {
  const fs::path dir = testing::test_dir();
  const fs::path sidecar = dir / "s.vdfx.json";
  fs::copy_file(kSrc + "/app/demo/interior.vdfx.json", sidecar);
  fs::copy_file(sidecar, fs::path(sidecar.string() + ".autosave"));
  const auto out = run_vdfx("edit --sidecar " + sidecar.string() + " --input replay:" + kRecording +
                            " --frames 2 --hidden --scale 0.05 --window 64x64 </dev/null");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("--recover yes"), std::string::npos) << out.output;
  // Not interactive: not loaded, set aside (the clean exit must not delete it).
  EXPECT_TRUE(fs::exists(fs::path(sidecar.string() + ".autosave.declined"))) << out.output;
  EXPECT_FALSE(fs::exists(fs::path(sidecar.string() + ".autosave"))) << out.output;

  // --recover yes loads it: a recovery copy with one more keyframe comes back as the sidecar.
  io::Sidecar changed = io::read_sidecar(sidecar);
  changed.effects.front().keyframes.push_back({{10.0, 20.0}, 0, {1.1, 1.0, 0.9}});
  io::write_sidecar(fs::path(sidecar.string() + ".autosave"), changed);
  const auto yes = run_vdfx("edit --sidecar " + sidecar.string() +
                            " --recover yes --input replay:" + kRecording +
                            " --frames 1 --hidden --scale 0.05 --window 64x64");
  ASSERT_EQ(yes.exit_code, 0) << yes.output;
  EXPECT_EQ(io::read_sidecar(sidecar).effects.front().keyframes.size(),
            changed.effects.front().keyframes.size())
      << yes.output;
}

TEST(EditCmdGl, ASecondEditorOpensReadOnlyAndItsEditsGoToACopy) {
  // Issue 23: two editors on one sidecar, each autosaving over the other. The first (a second,
  // real process holding the lock) keeps the sidecar; this one is told and opens read-only.
  const fs::path dir = testing::test_dir();
  const fs::path sidecar = dir / "s.vdfx.json", png = dir / "readonly.png";
  fs::copy_file(kSrc + "/app/demo/interior.vdfx.json", sidecar);
  const std::string before = test_files::slurp(sidecar);
  // The first editor's recovery copy, in use: a read-only session must leave it alone.
  fs::copy_file(sidecar, fs::path(sidecar.string() + ".autosave"));
  test_files::LockHolder first(sidecar);
  const auto out = run_vdfx("edit --sidecar " + sidecar.string() + " --input replay:" + kRecording +
                            " --hidden --scale 0.05 --window 320x180 --screenshot " + png.string() +
                            " </dev/null");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find(sidecar.string() + " is open in vdfx edit (process " +
                            std::to_string(first.pid())),
            std::string::npos)
      << out.output;
  EXPECT_NE(out.output.find("opening it READ-ONLY"), std::string::npos) << out.output;
  EXPECT_EQ(test_files::slurp(sidecar), before) << "the first editor's sidecar is untouched";
  EXPECT_TRUE(fs::exists(fs::path(sidecar.string() + ".autosave")));
  EXPECT_FALSE(fs::exists(fs::path(sidecar.string() + ".autosave.declined")));
  // The session's edits (the recording places two exposure keyframes) are in the copy.
  fs::path copy;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind("s-copy-", 0) == 0 &&
        e.path().filename().string().find(".autosave") == std::string::npos)
      copy = e.path();
  ASSERT_FALSE(copy.empty()) << out.output;
  EXPECT_NE(out.output.find(copy.string()), std::string::npos) << out.output;
  const io::Sidecar edited = io::read_sidecar(copy);
  EXPECT_NE(edited, io::read_sidecar(sidecar));
  EXPECT_TRUE(fs::exists(png));

  // The first editor is gone (killed: its lock stays behind): the next one takes it over.
  first.kill();
  const auto next = run_vdfx("edit --sidecar " + sidecar.string() +
                             " --access write --recover no --input replay:" + kRecording +
                             " --frames 2 --hidden --scale 0.05 --window 64x64 </dev/null");
  ASSERT_EQ(next.exit_code, 0) << next.output;
  EXPECT_NE(next.output.find("took over the lock left by vdfx edit (process"), std::string::npos)
      << next.output;
  EXPECT_FALSE(fs::exists(io::lock_path(sidecar))) << "released at exit";
}

}  // namespace
}  // namespace vdfx::app
