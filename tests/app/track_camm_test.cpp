/// @file
/// @brief The camera's orientation from a video's CAMM track (app/track/camm_motion.h), from an
/// MP4 written in the test: angle-axis orientations and, without them, gyroscope samples
/// integrated, each against the path they were made from; frame 0 is the world.
#include <gtest/gtest.h>

#include "app/bench/track_clips.h"
#include "app/track/camm_motion.h"
#include "io/camm_track.h"
#include "io/input_error.h"
#include "tests/app/command_test_util.h"
#include "tests/camm_clip.h"
#include "tests/media_clips.h"

namespace vdfx::app::track {
namespace {

namespace fs = std::filesystem;
using app::testing::test_dir;
using test_media::CammPacket;

constexpr int kFrames = 30;  // 1 s at 30 fps

/// The turn path (bench::CameraPath::Turn) at time t, seconds.
Eigen::Quaterniond turn_at(double t) {
  // camera_path samples its path at i / fps: one sample at fps = 1 / t is the path at t.
  return t <= 0.0 ? Eigen::Quaterniond::Identity()
                  : bench::camera_path(bench::CameraPath::Turn, 2, 1.0 / t)[1];
}

fs::path plain_clip(const fs::path& dir) {
  test_media::ClipSpec c;
  c.frames = kFrames;
  c.fps = {30, 1};
  return test_media::write_clip(dir / "plain.mp4", c);
}

std::vector<double> frame_times() {
  std::vector<double> t;
  for (int i = 0; i < kFrames; ++i) t.push_back(i / 30.0);
  return t;
}

double worst_error(const CammMotion& m) {
  const auto truth = bench::camera_path(bench::CameraPath::Turn, kFrames, 30.0);
  EXPECT_EQ(m.orientation.size(), truth.size());
  return bench::orientation_errors(m.orientation, truth).max;
}

TEST(TrackCamm, AngleAxisOrientationsAreSampledAtEachFrame) {
  const fs::path dir = test_dir();
  std::vector<CammPacket> packets;
  // 100 records a second, starting before the first frame; frame 0's becomes the world.
  const Eigen::Quaterniond offset(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()));
  for (int k = 0; k <= 100; ++k) {
    const Eigen::AngleAxisd aa(offset * turn_at(k / 100.0));
    const Eigen::Vector3d v = aa.angle() * aa.axis();
    packets.push_back({k / 100.0, 0, {float(v.x()), float(v.y()), float(v.z())}});
  }
  test_media::write_camm_clip(plain_clip(dir), dir / "camm.mp4", packets);
  const auto track = io::read_camm_track(dir / "camm.mp4");
  ASSERT_TRUE(track);
  const CammMotion m = camm_motion(*track, frame_times(), "camm.mp4");
  EXPECT_EQ(m.kind, CammMotion::Kind::AngleAxis);
  EXPECT_EQ(m.records, 101u);
  EXPECT_LT(bench::rotation_error_deg(m.orientation[0], Eigen::Quaterniond::Identity()), 1e-9);
  EXPECT_LT(worst_error(m), 0.01);
}

TEST(TrackCamm, GyroscopeSamplesAreIntegrated) {
  const fs::path dir = test_dir();
  std::vector<CammPacket> packets;
  // 200 samples a second of the body rate (about the camera's own axes), the derivative of the
  // path by central differences.
  const double h = 1e-4;
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    const Eigen::AngleAxisd d(turn_at(std::max(0.0, t - h)).conjugate() * turn_at(t + h));
    const Eigen::Vector3d w = d.angle() * d.axis() / (t - h < 0 ? t + h : 2 * h);
    packets.push_back({t, 2, {float(w.x()), float(w.y()), float(w.z())}});
  }
  // An accelerometer record in between: not used.
  packets.insert(packets.begin() + 100,
                 CammPacket{packets[99].time_s + 0.001, 3, {0.f, -9.8f, 0.f}});
  test_media::write_camm_clip(plain_clip(dir), dir / "gyro.mp4", packets);
  const auto track = io::read_camm_track(dir / "gyro.mp4");
  ASSERT_TRUE(track);
  const CammMotion m = camm_motion(*track, frame_times(), "gyro.mp4");
  EXPECT_EQ(m.kind, CammMotion::Kind::Gyro);
  EXPECT_LT(worst_error(m), 0.05);
}

TEST(TrackCamm, ATrackWithNeitherOrientationsNorGyroscopeIsAnInputError) {
  io::CammTrack only_other;
  only_other.other_records = 3;
  try {
    camm_motion(only_other, frame_times(), "clip.mp4");
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("clip.mp4: the CAMM track has neither"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace vdfx::app::track
