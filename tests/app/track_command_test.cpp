/// @file
/// @brief `vdfx track camera|subject|rename` through the real executable (docs/anchors.md): what
/// it writes into the sidecar and says, the CAMM track offered and used, a track added beside
/// others and replaced only when asked, every hidden frame reported, a track renamed with the
/// anchors naming it, and bad input with the contract's exit codes; and the library calls the
/// editor makes (progress, cancel).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/track/track.h"
#include "io/sidecar.h"
#include "tests/app/command_test_util.h"
#include "tests/app/track_test_util.h"
#include "tests/camm_clip.h"
#include "tests/lock_holder.h"
#include "tests/test_files.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;

std::vector<Eigen::Quaterniond> orientations(const io::Sidecar& s) {
  std::vector<Eigen::Quaterniond> q;
  if (s.camera)
    for (const effects::Quat& o : s.camera->orientation) q.push_back(effects::to_eigen(o));
  return q;
}

std::string at_of(const bench::SubjectPose& p, int frame) {
  const effects::Direction d = effects::from_unit(p.centre());
  return std::to_string(d.azimuth_deg) + "," + std::to_string(d.altitude_deg) + "," +
         std::to_string(frame);
}

TEST(TrackCommand, CameraWritesOneOrientationPerFrameFromFrameZero) {
  const fs::path dir = test_dir();
  const auto clip = write_camera_clip(dir / "turn.mp4", bench::CameraPath::Turn, 30, 512);
  const auto r = run_vdfx("track camera " + clip.path.string() + " --sidecar-out " +
                          (dir / "s.vdfx.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("camera: estimated from the pictures (512 pixels a turn"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("CAMM"), std::string::npos) << r.output;
  const io::Sidecar s = io::read_sidecar(dir / "s.vdfx.json");
  ASSERT_TRUE(s.camera);
  EXPECT_EQ(s.camera->source, effects::CameraMotion::Source::Estimated);
  ASSERT_EQ(s.camera->orientation.size(), 30u);
  EXPECT_EQ(s.camera->orientation[0], (effects::Quat{1, 0, 0, 0}));
  const auto err = bench::orientation_errors(orientations(s), clip.truth);
  EXPECT_LE(err.rms, 0.1);
  EXPECT_LE(err.max, 0.3);
}

TEST(TrackCommand, CameraOffersAndUsesTheVideosCammTrack) {
  const fs::path dir = test_dir();
  const auto clip = write_camera_clip(dir / "turn.mp4", bench::CameraPath::Turn, 30, 256);
  std::vector<test_media::CammPacket> packets;
  for (std::size_t i = 0; i < clip.truth.size(); ++i) {
    const Eigen::AngleAxisd aa(clip.truth[i]);
    const Eigen::Vector3d v = aa.angle() * aa.axis();
    packets.push_back({i / 30.0, 0, {float(v.x()), float(v.y()), float(v.z())}});
  }
  const fs::path camm = dir / "camm.mp4";
  test_media::write_camm_clip(clip.path, camm, packets);
  const std::string out = " --sidecar-out " + (dir / "s.vdfx.json").string();
  const auto offered = run_vdfx("track camera " + camm.string() + out);
  ASSERT_EQ(offered.exit_code, 0) << offered.output;
  EXPECT_NE(offered.output.find("the video carries a CAMM track (30 angle-axis orientations, 0 "
                                "gyroscope samples): --source camm uses it"),
            std::string::npos)
      << offered.output;
  // Onto the sidecar just written: its estimated camera is replaced, and the command says so.
  const auto used = run_vdfx("track camera " + camm.string() + " --source camm" + out);
  ASSERT_EQ(used.exit_code, 0) << used.output;
  EXPECT_NE(
      used.output.find("camera: the video's CAMM track: angle-axis orientations (30 records)"),
      std::string::npos)
      << used.output;
  EXPECT_NE(used.output.find("the sidecar's camera (source: estimated) is replaced"),
            std::string::npos)
      << used.output;
  const io::Sidecar s = io::read_sidecar(dir / "s.vdfx.json");
  ASSERT_TRUE(s.camera);
  EXPECT_EQ(s.camera->source, effects::CameraMotion::Source::Camm);
  // The records' times are kept to 0.1 ms (the test's track), 0.004 degrees of this turn.
  EXPECT_LE(bench::orientation_errors(orientations(s), clip.truth).max, 0.005);
  const auto none = run_vdfx("track camera " + clip.path.string() + " --source camm" + out);
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find(clip.path.string() + ": --source camm: the video has no CAMM track"),
            std::string::npos)
      << none.output;
}

TEST(TrackCommand, SubjectTracksAreAddedBesideOthersAndReplacedOnlyWhenAsked) {
  const fs::path dir = test_dir();
  const auto clip = write_subject_clip(dir / "seam.mp4", bench::SubjectMotion::Seam, 30, 512);
  const std::string base = "track subject " + clip.path.string() + " --size 10 --at " +
                           at_of(clip.truth[15], 15) + " --sidecar-out " +
                           (dir / "s.vdfx.json").string() + " --name ";
  const auto first = run_vdfx(base + "ball");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("track 'ball': 30 frames, seen in 30"), std::string::npos)
      << first.output;
  const auto second = run_vdfx(base + "ball-2");
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_NE(second.output.find("added to the existing"), std::string::npos) << second.output;
  const auto again = run_vdfx(base + "ball");
  EXPECT_EQ(again.exit_code, 1) << again.output;
  EXPECT_NE(again.output.find("/tracks/0/name: a track named 'ball' is already there; --replace"),
            std::string::npos)
      << again.output;
  ASSERT_EQ(run_vdfx(base + "ball --replace").exit_code, 0);
  const io::Sidecar s = io::read_sidecar(dir / "s.vdfx.json");
  ASSERT_EQ(s.tracks.size(), 2u);
  EXPECT_EQ(s.tracks[0].name, "ball");
  EXPECT_EQ(s.tracks[1].name, "ball-2");
  ASSERT_EQ(s.tracks[0].points.size(), 30u);
  for (std::size_t f = 0; f < 30; ++f) {
    const effects::TrackPoint& p = s.tracks[0].points[f];
    EXPECT_EQ(p.frame, static_cast<std::int64_t>(f));
    EXPECT_GT(p.confidence, 0.5);
    EXPECT_LE(effects::angle_between(effects::to_unit(p.direction), clip.truth[f].centre()) *
                  effects::kRadToDeg,
              1.0)
        << "frame " << f;
  }
}

/// Two tracks over 20 frames ("ball" turning 2 degrees a frame, "other" still), a saturation
/// anchored to ball, a flare anchored to ball, an exposure anchored to other.
io::Sidecar two_track_sidecar() {
  io::Sidecar s = io::new_sidecar({"clip.mp4", 30.0, 20, 512, 256});
  effects::SubjectTrack ball{"ball", {}}, other{"other", {}};
  for (int f = 0; f < 20; ++f) {
    ball.points.push_back({f, {2.0 * f, 5.0}, 0.9});
    other.points.push_back({f, {-90.0, 0.0}, 0.9});
  }
  s.tracks = {ball, other};
  effects::EffectTrack sat;
  sat.type = effects::EffectType::Saturation;
  sat.anchor = {effects::Anchor::Kind::Track, "ball"};
  sat.keyframes = {{{0.0, 5.0}, 0, {2.0}}, {{-60.0, 0.0}, 0, {0.2}}};
  effects::EffectTrack exposure;
  exposure.type = effects::EffectType::Exposure;
  exposure.anchor = {effects::Anchor::Kind::Track, "other"};
  exposure.keyframes = {{{-90.0, 0.0}, 0, {1.0}}, {{0.0, 0.0}, 0, {0.0}}};
  s.effects = {sat, exposure};
  effects::FlareEffect flare;
  flare.anchor = {effects::Anchor::Kind::Track, "ball"};
  flare.keyframes = {{{0.0, 5.0}, 0, {1.0}}};
  s.flares = {flare};
  return s;
}

TEST(TrackCommand, RenameRenamesTheTrackAndEveryAnchorNamingItAndRefusesClashes) {
  const fs::path dir = test_dir();
  const fs::path file = dir / "r.vdfx.json";
  io::write_sidecar(file, two_track_sidecar());
  const std::string views = " --at 20,5,10 --at -40,0,15 --at -90,0,3";
  const auto before = run_vdfx("eval " + file.string() + views);
  ASSERT_EQ(before.exit_code, 0) << before.output;

  const auto renamed = run_vdfx("track rename ball actor --sidecar-out " + file.string());
  ASSERT_EQ(renamed.exit_code, 0) << renamed.output;
  EXPECT_NE(renamed.output.find("track 'ball' renamed 'actor' (2 anchors)"), std::string::npos)
      << renamed.output;
  const io::Sidecar s = io::read_sidecar(file);
  ASSERT_EQ(s.tracks.size(), 2u);
  EXPECT_EQ(s.tracks[0].name, "actor");
  EXPECT_EQ(s.tracks[1].name, "other");
  EXPECT_EQ(s.tracks[0].points, two_track_sidecar().tracks[0].points);
  EXPECT_EQ(effects::anchor_name(s.effects[0].anchor), "track:actor");
  EXPECT_EQ(effects::anchor_name(s.effects[1].anchor), "track:other");
  EXPECT_EQ(effects::anchor_name(s.flares[0].anchor), "track:actor");
  // The effects evaluate exactly as before: only the name changed.
  const auto after = run_vdfx("eval " + file.string() + views);
  EXPECT_EQ(after.output, before.output);

  // Refused, the file left as it was: a name not there, a name taken, a name not allowed, an
  // editor holding the file.
  const std::string kept = test_files::slurp(file);
  const auto missing = run_vdfx("track rename ball x --sidecar-out " + file.string());
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(
      missing.output.find("r.vdfx.json: /tracks: no track named 'ball' (it has actor, other)"),
      std::string::npos)
      << missing.output;
  const auto taken = run_vdfx("track rename actor other --sidecar-out " + file.string());
  EXPECT_EQ(taken.exit_code, 1) << taken.output;
  EXPECT_NE(taken.output.find("/tracks/1/name: a track named 'other' is already there"),
            std::string::npos)
      << taken.output;
  EXPECT_EQ(run_vdfx("track rename actor 'a b' --sidecar-out " + file.string()).exit_code, 2);
  {
    test_files::LockHolder editor(file);
    const auto locked = run_vdfx("track rename actor b --sidecar-out " + file.string());
    EXPECT_EQ(locked.exit_code, 1) << locked.output;
  }
  const auto nothing = run_vdfx("track rename actor b --sidecar-out " + (dir / "no.json").string());
  EXPECT_EQ(nothing.exit_code, 1) << nothing.output;
  EXPECT_NE(nothing.output.find("no.json: no such sidecar"), std::string::npos) << nothing.output;
  EXPECT_EQ(test_files::slurp(file), kept);

  // From --sidecar-in into another file: the input is left alone.
  const fs::path copy = dir / "copy.vdfx.json";
  ASSERT_EQ(run_vdfx("track rename actor walker --sidecar-in " + file.string() + " --sidecar-out " +
                     copy.string())
                .exit_code,
            0);
  EXPECT_EQ(test_files::slurp(file), kept);
  EXPECT_EQ(io::read_sidecar(copy).tracks[0].name, "walker");
}

TEST(TrackCommand, SubjectSaysWhichFramesItHeld) {
  const fs::path dir = test_dir();
  const auto clip =
      write_subject_clip(dir / "approach.mp4", bench::SubjectMotion::Approach, 50, 512);
  const auto r =
      run_vdfx("track subject " + clip.path.string() + " --name car --size " +
               std::to_string(clip.truth[35].size_deg) + " --at " + at_of(clip.truth[35], 35) +
               " --sidecar-out " + (dir / "s.vdfx.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("not seen (last confident direction held, confidence 0) at 10 frames: "
                          "20-29"),
            std::string::npos)
      << r.output;
  const io::Sidecar s = io::read_sidecar(dir / "s.vdfx.json");
  ASSERT_EQ(s.tracks.size(), 1u);
  for (int f = 20; f < 30; ++f) {
    EXPECT_EQ(s.tracks[0].points[f].confidence, 0.0);
    // Held: the last confident direction (going backwards from frame 35, frame 30's).
    EXPECT_EQ(s.tracks[0].points[f].direction, s.tracks[0].points[30].direction);
  }
}

}  // namespace
}  // namespace vdfx::app::testing
