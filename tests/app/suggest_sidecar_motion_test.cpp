/// @file
/// @brief `vdfx suggest` with what `vdfx track` records (docs/suggest.md): a point of interest that
/// is a subject track (`--poi track:NAME`, followed as it moves, held where the tracker lost it),
/// and the comfort vignette from the sidecar's camera motion instead of one measured again.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "app/suggest/comfort.h"
#include "app/suggest/guide.h"
#include "app/suggest/suggest.h"
#include "effects/rbf_interpolator.h"
#include "io/sidecar.h"
#include "tests/app/command_test_util.h"

namespace vdfx::app::suggest {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx_headless;
using testing::test_dir;

constexpr int kFrames = 30, kFps = 10;

/// A still camera: `kFrames` frames of one smoothed-noise 256x128 equirect, MJPG at 10 fps.
fs::path still_clip(const fs::path& dir) {
  cv::Mat noise(128, 256, CV_8UC3), pano;
  cv::RNG(3).fill(noise, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(noise, pano, cv::Size(0, 0), 2.0);
  const fs::path clip = dir / "still.avi";
  cv::VideoWriter w(clip.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kFps, pano.size());
  EXPECT_TRUE(w.isOpened());
  for (int i = 0; i < kFrames; ++i) w << pano;
  return clip;
}

io::Sidecar blank_sidecar(const fs::path& clip) {
  return io::new_sidecar({clip.string(), static_cast<double>(kFps), kFrames, 256, 128});
}

/// The subject's true direction: from azimuth -90 at frame 0 across the front at 2 degrees a
/// frame.
double subject_az(std::int64_t f) {
  return -90.0 + 2.0 * static_cast<double>(f);
}

/// A track "actor" following subject_az, lost from frame 20 on (confidence 0, a direction that is
/// not the subject's: readers hold the last one seen).
effects::SubjectTrack actor_track() {
  effects::SubjectTrack t{"actor", {}};
  for (std::int64_t f = 0; f < kFrames; ++f)
    t.points.push_back(f < 20 ? effects::TrackPoint{f, {subject_az(f), 0.0}, 0.9}
                              : effects::TrackPoint{f, {180.0, 0.0}, 0.0});
  return t;
}

double saturation_at(const io::Sidecar& s, const effects::Direction& d, std::int64_t frame) {
  for (const auto& t : s.effects)
    if (t.type == effects::EffectType::Saturation) {
      const effects::RbfInterpolator f(t.keyframes, 1, t.interpolation.value_or(s.interpolation),
                                       s.video.fps, effects::effect_spec(t.type).neutral());
      return f.evaluate(d, frame)[0];
    }
  ADD_FAILURE() << "no saturation";
  return 0.0;
}

TEST(SuggestGuideTrack, FollowsTheSubjectAndHoldsWhereItWasLost) {
  const fs::path dir = test_dir();
  SuggestRequest r;
  r.kind = Kind::Guide;
  r.video = still_clip(dir);
  io::Sidecar in = blank_sidecar(r.video);
  in.tracks = {actor_track()};
  r.sidecar_in = dir / "in.vdfx.json";
  io::write_sidecar(*r.sidecar_in, in);
  r.sidecar_out = dir / "out.vdfx.json";
  r.every = 2;
  r.points = {parse_point_of_interest("track:actor")};
  run_suggest(r);
  const io::Sidecar s = io::read_sidecar(r.sidecar_out);
  const double tol = kSaturationTolerance + 0.03;
  for (const std::int64_t f : {4, 10, 16}) {  // neutral on the subject, guided away from it
    EXPECT_NEAR(saturation_at(s, {subject_az(f), 0.0}, f), 1.0, tol) << f;
    EXPECT_LT(saturation_at(s, {subject_az(f) + 180.0, 0.0}, f), 0.3) << f;
  }
  // Lost from frame 20: held where it was last seen (frame 19), not where the track says.
  EXPECT_NEAR(saturation_at(s, {subject_az(19), 0.0}, 26), 1.0, 0.1);
  EXPECT_LT(saturation_at(s, {subject_az(19) + 180.0, 0.0}, 26), 0.3);
}

TEST(SuggestGuideTrack, ATrackTheSidecarLacksNamesTheOptionAndTheSidecar) {
  const fs::path dir = test_dir();
  const fs::path clip = still_clip(dir), in = dir / "in.vdfx.json";
  io::Sidecar s = blank_sidecar(clip);
  s.tracks = {actor_track()};
  io::write_sidecar(in, s);
  const auto r =
      run_vdfx_headless("suggest guide " + clip.string() + " --sidecar-in " + in.string() +
                        " --sidecar-out " + (dir / "o.vdfx.json").string() + " --poi track:nobody");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--poi track:nobody: " + in.string() +
                          " has no track 'nobody' (it has: actor)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "o.vdfx.json"));
  // A name no track may have is a usage error.
  EXPECT_EQ(run_vdfx_headless("suggest guide " + clip.string() + " --sidecar-out " +
                              (dir / "o.vdfx.json").string() + " --poi 'track:a b'")
                .exit_code,
            2);
}

TEST(SuggestComfortCamera, TheVignetteFollowsTheSidecarsCameraMotion) {
  // The pictures stand still; the recorded camera is still for 15 frames, then turns at 9 degrees
  // a frame (90 deg/s at 10 fps).
  const fs::path dir = test_dir();
  SuggestRequest r;
  r.kind = Kind::Comfort;
  r.video = still_clip(dir);
  io::Sidecar in = blank_sidecar(r.video);
  effects::CameraMotion camera;
  camera.source = effects::CameraMotion::Source::Given;
  for (int f = 0; f < kFrames; ++f) {
    const double yaw = 9.0 * std::max(0, f - 15) * effects::kDegToRad;
    camera.orientation.push_back(
        effects::from_eigen(Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()))));
  }
  in.camera = camera;
  r.sidecar_in = dir / "in.vdfx.json";
  io::write_sidecar(*r.sidecar_in, in);
  r.sidecar_out = dir / "out.vdfx.json";
  const SuggestReport report = run_suggest(r);
  EXPECT_NE(report.motion_note.find("using the sidecar's camera motion (given"), std::string::npos)
      << report.motion_note;
  ASSERT_EQ(report.speed_deg_per_s.size(), static_cast<std::size_t>(kFrames));
  EXPECT_NEAR(report.speed_deg_per_s[5], 0.0, 1e-6);
  EXPECT_NEAR(report.speed_deg_per_s[25], 90.0, 1e-6);
  const io::Sidecar s = io::read_sidecar(r.sidecar_out);
  ASSERT_EQ(s.effects.size(), 1u);
  const auto& t = s.effects[0];
  const effects::RbfInterpolator f(t.keyframes, 2, t.interpolation.value_or(s.interpolation),
                                   s.video.fps, effects::effect_spec(t.type).neutral());
  EXPECT_NEAR(f.evaluate(effects::Direction{0, 0}, 3)[0], comfort_radius_deg(0.0, 1.0),
              kVignetteToleranceDeg + 1);
  EXPECT_NEAR(f.evaluate(effects::Direction{0, 0}, 27)[0], comfort_radius_deg(90.0, 1.0),
              kVignetteToleranceDeg + 1);

  // Measured anyway, the still pictures give an open view throughout.
  r.measure_motion = true;
  r.force = true;
  const SuggestReport measured = run_suggest(r);
  EXPECT_TRUE(measured.motion_note.empty());
  EXPECT_LT(measured.speed_deg_per_s[25], 2.0);
}

TEST(SuggestComfortCamera, TheCommandSaysWhichMotionItUsed) {
  const fs::path dir = test_dir();
  const fs::path clip = still_clip(dir), in = dir / "in.vdfx.json";
  io::Sidecar s = blank_sidecar(clip);
  effects::CameraMotion camera;  // estimated, still
  camera.orientation.assign(kFrames, effects::Quat{1.0, 0.0, 0.0, 0.0});
  s.camera = camera;
  io::write_sidecar(in, s);
  const auto r =
      run_vdfx_headless("suggest comfort " + clip.string() + " --sidecar-in " + in.string() +
                        " --sidecar-out " + (dir / "o.vdfx.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("vdfx suggest: using the sidecar's camera motion (estimated"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace vdfx::app::suggest
