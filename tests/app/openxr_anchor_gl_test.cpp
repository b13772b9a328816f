/// @file
/// @brief A headset session through the simulated OpenXR runtime (core validation layer on)
/// placing a keyframe on a world-anchored effect while the film plays and its camera turns: the
/// editor plays the turning clip (the demo room turned 18 degrees a frame, the sidecar's camera
/// given), the scripted head looks at one place and pulls the trigger; the stored keyframe is
/// q_f n, the scripted gaze n turned by the camera of the frame f it was placed at.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "app/bench/turning_clip.h"
#include "app/editor/editor.h"
#include "app/window/editor_client.h"
#include "app/window/frame_loop.h"
#include "io/sidecar.h"
#include "io/video_source.h"
#include "tests/app/openxr_editor_loop.h"
#include "tests/app/openxr_test_support.h"
#include "xr/input/input_backend.h"
#include "xr/openxr/gl/openxr_runtime.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::gaze_script;
using testing::write_script;

constexpr int kFrames = 20, kFps = 10;

class OpenXrAnchor : public testing::OpenXrTest {};

TEST_F(OpenXrAnchor, ATriggerPressPlacesTheGazeTurnedByTheCameraOfItsFrame) {
  const fs::path clip = dir() / "turn.mp4";
  bench::write_turning_clip(clip, bench::interior_panorama(128), kFrames, 360.0, kFps);
  const effects::CameraMotion camera = bench::turning_camera(kFrames, 360.0);
  io::Sidecar sidecar = bench::turning_sidecar({"turn.mp4", kFps, kFrames, 128, 64}, camera,
                                               {effects::Anchor::Kind::World, {}});
  const effects::Direction gaze{-25.0, 12.0};
  write_script(dir() / "s.vdrec.jsonl",
               gaze_script(gaze.azimuth_deg, gaze.altitude_deg, 45, 15, 30));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  env_->apply();
  for (const auto& [k, v] : knobs_) setenv(k.c_str(), v.c_str(), 1);

  auto video = io::VideoSource::open(clip, {});
  const std::unique_ptr<Editor> editor = testing::headset_test_editor(sidecar);
  editor->set_playing(true);  // the film plays: the camera turns under the placement
  EditorClient client(*editor, create_gl_panel_textures());
  FrameLoopOptions o = testing::openxr_loop_options();
  auto input = o.openxr->create_input_backend();
  {
    FrameLoop loop(o, *input, *video, client);
    loop.run();
    client.release_textures();
  }
  input.reset();
  for (const auto& [k, v] : knobs_) unsetenv(k.c_str());

  const auto& ks = editor->document().keyframes(effects::EffectType::Exposure);
  ASSERT_EQ(ks.size(), 3u) << "the window, behind it, and the one placed";
  const effects::Keyframe& placed = ks.back();
  EXPECT_GT(placed.frame, 0) << "placed while the camera has turned";
  const Eigen::Quaterniond q = effects::to_eigen(camera.orientation.at(placed.frame));
  const Eigen::Vector3d want = q * effects::to_unit(gaze);
  const Eigen::Vector3d got = effects::to_unit(placed.direction);
  EXPECT_LT(std::atan2(got.cross(want).norm(), got.dot(want)) * effects::kRadToDeg, 0.1)
      << "placed at " << placed.direction.azimuth_deg << ", " << placed.direction.altitude_deg
      << " frame " << placed.frame << "; the gaze turned by q_f is "
      << effects::from_unit(want).azimuth_deg << ", " << effects::from_unit(want).altitude_deg;
  // Not the gaze itself: the camera had turned by then.
  EXPECT_GT(std::atan2(got.cross(effects::to_unit(gaze)).norm(), got.dot(effects::to_unit(gaze))) *
                effects::kRadToDeg,
            5.0);
}

}  // namespace
}  // namespace vdfx::app
