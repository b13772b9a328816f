/// @file
/// @brief The headless long commands stopped by real signals (docs/cli.md, "Stopping a command"):
/// `vdfx replay` (SIGINT) and `vdfx suggest` (SIGHUP) write nothing, leave --sidecar-out as it
/// was and release its lock, as `vdfx track camera` (SIGTERM) does; `vdfx publish --transcode`
/// (SIGINT) leaves OUT as it was and removes its staging folder. Each process ends by the signal
/// and says so.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/file_lock.h"
#include "io/recording.h"
#include "tests/app/command_test_util.h"
#include "tests/app/publish_test_util.h"
#include "tests/app/signal_test_support.h"
#include "tests/media_clips.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::VdfxProcess;

/// The process ended by `sig` and said "vdfx COMMAND: stopped by NAME: WHAT".
void expect_stopped(VdfxProcess& p, int sig, const std::string& said) {
  const int status = p.wait();
  const std::string out = p.output();
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig)
      << testing::describe_status(status) << "\n"
      << out;
  EXPECT_NE(out.find(said), std::string::npos) << out;
}

/// A smooth colourful H.264 clip.
fs::path clip(const fs::path& dir, int width, int height, int frames) {
  test_media::ClipSpec c;
  c.width = width;
  c.height = height;
  c.frames = frames;
  c.frame = [=](int i) { return test_media::smooth_frame(i, width, height); };
  return test_media::write_clip(dir / "clip.mp4", c);
}

/// A sim session of `samples` samples looking around (nothing pressed).
fs::path idle_session(const fs::path& dir, int samples) {
  const fs::path out = dir / "idle.vdrec.jsonl";
  io::RecordingHeader h;
  h.note = "idle";
  io::RecordingWriter w(out, h);
  io::RecordedSample s;
  s.head.p = {0.0, 1.6, 0.0};
  for (int i = 0; i < samples; ++i) {
    s.t_ns = (i + 1) * 11'111'111LL;
    w.write(s);
  }
  return out;
}

TEST(StopSignalsCmd, SigintStopsAReplayWithItsSidecarOutAsItWas) {
  const fs::path dir = testing::test_dir();
  const fs::path pano = testing::write_test_panorama(dir), out = dir / "s.vdfx.json";
  testing::write_text(out, testing::exposure_sidecar());
  const std::string before = test_files::slurp(out);
  const fs::path session = idle_session(dir, 200000);
  VdfxProcess replay(
      {"replay", session.string(), "--video", pano.string(), "--sidecar-out", out.string()},
      dir / "replay.log");
  // The lock is taken before any work; the recording takes a while to read and replay.
  ASSERT_TRUE(replay.wait_until([&] { return fs::exists(io::lock_path(out)); })) << replay.output();
  replay.signal(SIGINT);
  expect_stopped(replay, SIGINT, "vdfx replay: stopped by SIGINT: replayed ");
  EXPECT_NE(replay.output().find(" samples; nothing written, " + out.string() + " left as it was"),
            std::string::npos)
      << replay.output();
  EXPECT_EQ(test_files::slurp(out), before);
  EXPECT_FALSE(fs::exists(io::lock_path(out)));
}

TEST(StopSignalsCmd, SighupStopsASuggestionWithItsSidecarOutAsItWas) {
  const fs::path dir = testing::test_dir();
  const fs::path video = clip(dir, 128, 64, 120);
  const fs::path out = dir / "s.vdfx.json";
  testing::write_text(out, testing::exposure_sidecar());
  const std::string before = test_files::slurp(out);
  VdfxProcess suggest({"suggest", "exposure", video.string(), "--sidecar-out", out.string(),
                       "--merge", "--every", "1", "--directions", "5000"},
                      dir / "suggest.log");
  ASSERT_TRUE(suggest.wait_until([&] { return fs::exists(io::lock_path(out)); }))
      << suggest.output();
  suggest.signal(SIGHUP);
  expect_stopped(
      suggest, SIGHUP,
      "vdfx suggest: stopped by SIGHUP: nothing written; " + out.string() + " left as it was");
  EXPECT_EQ(test_files::slurp(out), before);
  EXPECT_FALSE(fs::exists(io::lock_path(out)));
}

TEST(StopSignalsCmd, SigtermStopsACameraTrackWithNothingWritten) {
  const fs::path dir = testing::test_dir();
  const fs::path video = clip(dir, 128, 64, 60), out = dir / "t.vdfx.json";
  // A wide analysis makes each frame slow enough to be stopped in the middle of the clip.
  VdfxProcess track({"track", "camera", video.string(), "--sidecar-out", out.string(), "--width",
                     "4096", "--points", "5000"},
                    dir / "track.log");
  ASSERT_TRUE(track.wait_until([&] { return fs::exists(io::lock_path(out)); })) << track.output();
  track.signal(SIGTERM);
  expect_stopped(
      track, SIGTERM,
      "vdfx track: stopped by SIGTERM: nothing written; " + out.string() + " left as it was");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(io::lock_path(out)));
}

/// The files of a folder with their contents, for "as it was".
std::map<std::string, std::string> folder(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = test_files::slurp(e);
  return files;
}

TEST(StopSignalsCmd, SigintDuringPublishTranscodeLeavesOutAsItWasAndNoStagingFolder) {
  // The sanitized build has no web module (publish is then an internal error naming it).
  if (!testing::module_built()) GTEST_SKIP() << testing::kNoModule;
  const fs::path dir = testing::test_dir();
  const fs::path video = clip(dir, 512, 256, 240);
  const fs::path sidecar = dir / "s.vdfx.json", out = dir / "site";
  testing::write_text(sidecar, testing::exposure_sidecar());
  const auto first = testing::run_vdfx("publish " + video.string() + " --sidecar " +
                                       sidecar.string() + " --out " + out.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto before = folder(out);

  VdfxProcess publish({"publish", video.string(), "--sidecar", sidecar.string(), "--out",
                       out.string(), "--transcode", "h264"},
                      dir / "publish.log");
  const fs::path staging = dir / (".site.publish-" + std::to_string(publish.pid()));
  // Stopped while the transcode writes its temporary file inside the staging folder.
  ASSERT_TRUE(publish.wait_until([&] {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(staging, ec))
      if (e.path().filename().string().find(".tmp-") != std::string::npos &&
          fs::file_size(e.path(), ec) > 0)
        return true;
    return false;
  })) << publish.output();
  publish.signal(SIGINT);
  expect_stopped(publish, SIGINT,
                 "vdfx publish: stopped by SIGINT: the staging folder removed; " + out.string() +
                     " left as it was");
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_EQ(folder(out), before);
}

}  // namespace
}  // namespace vdfx::app
