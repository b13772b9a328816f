/// @file
/// @brief `vdfx track` on bad input (docs/anchors.md, "Bad input"): exit 1 naming the file and the
/// JSON pointer or the option, exit 2 for usage; and its library calls as the editor makes them
/// (progress to the end, a cancel that leaves the sidecar as it was).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/track/track.h"
#include "io/sidecar.h"
#include "tests/app/command_test_util.h"
#include "tests/media_clips.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;

fs::path small_clip(const fs::path& dir, int w = 128, int h = 64) {
  test_media::ClipSpec c;
  c.frames = 10;
  c.width = w;
  c.height = h;
  return test_media::write_clip(dir / "clip.mp4", c);
}

void expect_error(const CommandResult& r, int code, const std::string& text) {
  EXPECT_EQ(r.exit_code, code) << r.output;
  EXPECT_NE(r.output.find(text), std::string::npos) << "missing \"" << text << "\" in\n"
                                                    << r.output;
}

/// A sidecar for the 10-frame clip with `camera` as its camera section.
fs::path sidecar_with(const fs::path& dir, const std::string& extra, int frames = 10) {
  const fs::path p = dir / "in.vdfx.json";
  write_text(p, R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "clip.mp4", "fps": 24.0, "frames": )" +
                    std::to_string(frames) + R"(, "width": 128, "height": 64},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": [])" +
                    extra + "}");
  return p;
}

TEST(TrackBadInput, AStillImageHasNothingToTrack) {
  const fs::path dir = test_dir();
  const fs::path pano = write_test_panorama(dir);
  const std::string out = " --sidecar-out " + (dir / "s.vdfx.json").string();
  expect_error(run_vdfx("track camera " + pano.string() + out), 1,
               pano.string() + ": is a still image: a camera or subject track needs a video");
  expect_error(run_vdfx("track subject " + pano.string() + " --name a --at 0,0,0" + out), 1,
               "is a still image");
  EXPECT_FALSE(fs::exists(dir / "s.vdfx.json"));
}

TEST(TrackBadInput, AtOutsideTheVideoNamesTheOption) {
  const fs::path dir = test_dir();
  const fs::path clip = small_clip(dir, 128, 128);
  const std::string base = "track subject " + clip.string() + " --name a --sidecar-out " +
                           (dir / "s.vdfx.json").string();
  expect_error(
      run_vdfx(base + " --coverage 180 --at 120,0,3"), 1,
      clip.string() + ": --at 120,0,3: outside the video's image (VR180: azimuth -90 to 90)");
  expect_error(run_vdfx(base + " --at 0,0,10"), 1,
               clip.string() + ": --at 0,0,10: frame 10 is not in the video (frames 0 to 9)");
  expect_error(run_vdfx(base + " --at 0,95,1"), 2, "--at");
  expect_error(run_vdfx("track subject " + clip.string() + " --name 'no spaces' --at 0,0,0 " +
                        "--sidecar-out " + (dir / "s.vdfx.json").string()),
               2, "--name must be 1 to 64 of");
  expect_error(run_vdfx(base + " --at 0,0,0 --size 0"), 2, "--size");
  expect_error(run_vdfx("track camera " + clip.string() + " --source gyro --sidecar-out x.json"), 2,
               "--source");
  EXPECT_FALSE(fs::exists(dir / "s.vdfx.json"));
}

TEST(TrackBadInput, ASidecarInWithABadCameraOrTrackNamesThePointer) {
  const fs::path dir = test_dir();
  const fs::path clip = small_clip(dir);
  const auto run = [&](const fs::path& in) {
    return run_vdfx("track subject " + clip.string() + " --name a --at 0,0,0 --sidecar-in " +
                    in.string() + " --sidecar-out " + (dir / "s.vdfx.json").string());
  };
  const std::string q = "[1, 0, 0, 0]";
  expect_error(run(sidecar_with(dir, R"(, "camera": {"source": "estimated", "orientation": [)" + q +
                                         "," + q + "]}")),
               1, "/camera/orientation: 2 orientations for a video of 10 frames");
  std::string ten_bad = "[2, 0, 0, 0]";
  for (int i = 1; i < 10; ++i) ten_bad += "," + q;
  expect_error(run(sidecar_with(
                   dir, R"(, "camera": {"source": "given", "orientation": [)" + ten_bad + "]}")),
               1, "/camera/orientation/0: not a unit quaternion");
  expect_error(run(sidecar_with(dir, R"(, "tracks": [{"name": "t", "points": [
      {"frame": 0, "azimuth_deg": 0, "altitude_deg": 0, "confidence": 1},
      {"frame": 2, "azimuth_deg": 0, "altitude_deg": 0, "confidence": 1}]}])")),
               1, "/tracks/0/points/1/frame");
  expect_error(run(sidecar_with(dir, "", 5)), 1, "/video/frames: 5 frames, but " + clip.string());
  EXPECT_FALSE(fs::exists(dir / "s.vdfx.json"));
}

TEST(TrackLibrary, ReportsProgressAndACancelLeavesTheSidecarAsItWas) {
  const fs::path dir = test_dir();
  const fs::path clip = small_clip(dir, 256, 128);
  io::Sidecar sidecar = io::new_sidecar({clip.string(), 24.0, 10, 256, 128});
  const io::Sidecar before = sidecar;
  track::CameraRequest r;
  r.video = clip;
  track::Progress progress;
  progress.cancel = true;
  EXPECT_THROW(track::track_camera_into(r, sidecar, &progress), track::Cancelled);
  EXPECT_EQ(sidecar, before);
  track::Progress go;
  track::track_camera_into(r, sidecar, &go);
  EXPECT_EQ(go.fraction.load(), 1.0);
  ASSERT_TRUE(sidecar.camera);
  EXPECT_EQ(sidecar.camera->orientation.size(), 10u);
  track::SubjectRequest s;
  s.video = clip;
  s.name = "stripes";
  s.frame = 4;
  track::Progress sp;
  track::track_subject_into(s, sidecar, &sp);
  EXPECT_EQ(sp.fraction.load(), 1.0);
  ASSERT_EQ(sidecar.tracks.size(), 1u);
  EXPECT_EQ(sidecar.tracks[0].points.size(), 10u);
}

}  // namespace
}  // namespace vdfx::app::testing
