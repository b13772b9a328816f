/// @file
/// @brief The world anchor end to end with an estimated camera (docs/anchors.md): a clip whose
/// camera turns along a known path (the forest panorama, app/bench/track_clips.h), its camera
/// estimated by `vdfx track camera`, an exposure keyframe fixed in the world on one place of it
/// (the room's window direction of the turning-clip tests), and `vdfx eval` at where that place
/// is in the video frame at each frame (from the true path): the exposure stays within 0.05 stops
/// of the keyframe over the turn, as with a given camera; fixed in the picture it does not.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/bench/turning_clip.h"
#include "command_test_util.h"
#include "io/sidecar.h"
#include "tests/app/track_test_util.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
constexpr int kFrames = 30;
constexpr int kAt[] = {0, 10, 20, 29};

/// `vdfx eval` at the window's direction of the video frame at each of kAt (the true camera):
/// the exposure it prints at each.
std::vector<double> eval_at_window(const fs::path& sidecar,
                                   const std::vector<Eigen::Quaterniond>& truth) {
  std::string args = "eval " + sidecar.string();
  for (const int f : kAt) {
    const Eigen::Vector3d v = truth[f].inverse() * effects::to_unit(bench::kRoomWindow);
    const effects::Direction d = effects::from_unit(v);
    std::ostringstream at;
    at.precision(17);
    at << " --at " << d.azimuth_deg << "," << d.altitude_deg << "," << f;
    args += at.str();
  }
  const testing::CommandResult r = testing::run_vdfx(args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::vector<double> stops;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);)
    stops.push_back(nlohmann::json::parse(line)["effects"]["exposure"]["stops"].get<double>());
  return stops;
}

TEST(AnchorTrack, AWorldAnchoredExposureHoldsAtItsPlaceWithTheTrackedCamera) {
  const fs::path dir = testing::test_dir();
  const testing::CameraClip clip =
      testing::write_camera_clip(dir / "turn.mp4", bench::CameraPath::Turn, kFrames, 512);
  const fs::path tracked = dir / "tracked.vdfx.json";
  const auto r = testing::run_vdfx("track camera " + clip.path.string() + " --sidecar-out " +
                                   tracked.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const io::Sidecar s = io::read_sidecar(tracked);
  ASSERT_TRUE(s.camera);
  const fs::path world = dir / "world.vdfx.json", video = dir / "video.vdfx.json";
  io::write_sidecar(world,
                    bench::turning_sidecar(s.video, *s.camera, {effects::Anchor::Kind::World, {}}));
  io::write_sidecar(video, bench::turning_sidecar(s.video, *s.camera, {}));
  const std::vector<double> held = eval_at_window(world, clip.truth);
  const std::vector<double> fixed = eval_at_window(video, clip.truth);
  ASSERT_EQ(held.size(), std::size(kAt));
  ASSERT_EQ(fixed.size(), std::size(kAt));
  for (std::size_t i = 0; i < held.size(); ++i)
    EXPECT_NEAR(held[i], bench::kWindowStops, 0.05) << "frame " << kAt[i];
  EXPECT_GT(std::abs(fixed.back() - bench::kWindowStops), 0.1)
      << "fixed in the picture, the keyframe has left the window a second into the turn";
}

}  // namespace
}  // namespace vdfx::app
