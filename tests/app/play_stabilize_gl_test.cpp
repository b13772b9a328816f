/// @file
/// @brief `vdfx play --stabilize` (docs/player.md, "Stabilised"; under Xvfb): the view shows the
/// world frame, so with the camera turned 90 degrees to the right the head looking ahead sees what
/// `vdfx render` shows of the video at azimuth 90, effects as they are there; and the pose
/// composition itself (app/window/stabilized_view.h) on rays.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "app/window/stabilized_view.h"
#include "tests/app/command_test_util.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::mean_abs_diff;
using testing::run_vdfx;

/// The exposure sidecar of the panorama (+1 stop at azimuth 90, -1 at -90) with one frame's
/// camera: turned by `yaw_deg` about +y (video azimuth 0 is at world azimuth -yaw).
std::string sidecar_with_camera(double yaw_deg) {
  const double h = 0.5 * yaw_deg * effects::kDegToRad;
  const std::string camera = R"(, "camera": {"source": "given", "orientation": [[)" +
                             std::to_string(std::cos(h)) + ", 0, " + std::to_string(std::sin(h)) +
                             ", 0]]}";
  std::string s = testing::exposure_sidecar();
  return s.substr(0, s.rfind('}')) + camera + "}";
}

TEST(PlayStabilizeGl, TheHeadLookingAheadSeesTheVideoWhereTheCameraTurnedFrom) {
  const fs::path dir = testing::panorama_and_sidecar();
  testing::write_text(dir / "s.vdfx.json", sidecar_with_camera(90.0));
  const fs::path png = dir / "play.png";
  const auto p = run_vdfx("play " + (dir / "pano.png").string() + " --sidecar " +
                          (dir / "s.vdfx.json").string() +
                          " --stabilize --frames 3 --window 160x80 --hidden --fov 100"
                          " --decode-timeout 5000 --screenshot " +
                          png.string());
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const cv::Mat shown = cv::imread(png.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(shown.empty());
  const cv::Mat at90 = testing::render(dir, "--view 90,0 --fov 100 --size 160x80", "r90.png");
  const cv::Mat at0 = testing::render(dir, "--view 0,0 --fov 100 --size 160x80", "r0.png");
  const double near = mean_abs_diff(shown, at90), far = mean_abs_diff(shown, at0);
  EXPECT_LT(near, 8.0) << "stabilised: the video at azimuth 90 (+1 stop)";
  EXPECT_GT(far, 4.0 * near) << "not the video frame's own azimuth 0";
}

TEST(PlayStabilizeGl, NeedsTheSidecarsCameraMotion) {
  const fs::path dir = testing::panorama_and_sidecar();
  const auto p = run_vdfx("play " + (dir / "pano.png").string() + " --sidecar " +
                          (dir / "s.vdfx.json").string() + " --stabilize --frames 1 --hidden");
  EXPECT_EQ(p.exit_code, 1) << p.output;
  EXPECT_NE(p.output.find((dir / "s.vdfx.json").string() +
                          ": --stabilize: the sidecar has no camera motion: run vdfx track camera"),
            std::string::npos)
      << p.output;
}

TEST(StabilizedView, ARayOfThePoseSamplesTheVideoAtTheInverseCameraRotation) {
  effects::CameraMotion camera;
  const Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond q1(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  camera.orientation = {effects::from_eigen(q0), effects::from_eigen(q1)};
  const effects::AnchorFrames world = effects::AnchorFrames::world(camera);
  xr::Pose head;
  head.orientation = glm::normalize(glm::dquat(0.9, 0.1, -0.3, 0.2));
  head.position = {0.1, 1.6, -0.2};
  const glm::dvec3 ray = glm::normalize(glm::dvec3(0.3, -0.2, -1.0));
  for (const std::int64_t f : {0, 1}) {
    const xr::Pose v = video_frame_pose(head, world, f);
    const glm::dvec3 w = head.rotate(ray), got = v.rotate(ray);
    // The contract: the picture's direction w shows the video at q_f^-1 w q_f.
    const Eigen::Vector3d want = (f == 0 ? q0 : q1).inverse() * Eigen::Vector3d(w.x, w.y, w.z);
    EXPECT_NEAR(got.x, want.x(), 1e-12) << f;
    EXPECT_NEAR(got.y, want.y(), 1e-12) << f;
    EXPECT_NEAR(got.z, want.z(), 1e-12) << f;
  }
  // The video anchor's frames (identity) leave the pose as it is.
  const xr::Pose same = video_frame_pose(head, effects::AnchorFrames{}, 1);
  EXPECT_EQ(same.orientation, head.orientation);
  EXPECT_EQ(same.position, head.position);
}

}  // namespace
}  // namespace vdfx::app
