/// @file
/// @brief The editor on VR180 video (docs/stereo.md): the minimap dims what the video does not
/// cover, and a keyframe placed outside the coverage is refused with a message (nothing placed,
/// nothing to undo); inside it places as on mono video.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using test::looking;

constexpr std::int64_t kFrame = 33'333'333;

io::Sidecar vr180_sidecar() {
  io::Sidecar s = test::empty_sidecar(90);
  s.video.layout = effects::StereoMode::LeftRight;
  s.video.coverage_deg = 180;
  return s;
}

class EditorVr180 : public ::testing::Test {
 protected:
  EditorVr180() : ed_(vr180_sidecar(), DocumentOptions{{.async = false}}, EditorOptions{}) {}
  /// Looks at (az, 0) with the right trigger pressed, then released: a preview, then a place.
  void place_at(double az) {
    auto in = looking(az, 0.0, t_ += kFrame);
    in.right.trigger = 1.0;
    ed_.update(sync_.sync(in), t_);
    t_ += kFrame;
    ed_.update(sync_.sync(looking(az, 0.0, t_)), t_);
  }
  std::size_t keyframes() { return ed_.document().keyframes(EffectType::Exposure).size(); }

  Editor ed_;
  xr::ActionSync sync_;
  std::int64_t t_ = 0;
};

TEST_F(EditorVr180, MinimapShowsTheCoverage) {
  t_ += kFrame;
  ed_.update(sync_.sync(looking(0.0, 0.0, t_)), t_);
  EXPECT_EQ(ed_.ui().minimap().coverage(), 180);
  Editor mono(test::empty_sidecar(90), DocumentOptions{{.async = false}}, EditorOptions{});
  EXPECT_EQ(mono.ui().minimap().coverage(), 360);
}

TEST_F(EditorVr180, PlacingOutsideTheCoverageSaysSoAndPlacesNothing) {
  place_at(120.0);
  EXPECT_EQ(keyframes(), 0u);
  EXPECT_NE(ed_.hud_message().find("outside the video (it covers azimuth -90 to 90): no keyframe "
                                   "placed"),
            std::string::npos)
      << ed_.hud_message();
  EXPECT_FALSE(ed_.undo());  // nothing happened to undo
  place_at(-179.0);
  EXPECT_EQ(keyframes(), 0u);
  place_at(45.0);
  ASSERT_EQ(keyframes(), 1u);
  EXPECT_NEAR(ed_.document().keyframes(EffectType::Exposure)[0].direction.azimuth_deg, 45.0, 1e-9);
  // In the 2-degree fade the picture still shows: a keyframe there is placed.
  place_at(89.0);
  EXPECT_EQ(keyframes(), 2u);
}

TEST_F(EditorVr180, TheSidecarKeepsTheLayout) {
  const io::Sidecar s = ed_.document().sidecar();
  EXPECT_EQ(s.video.stereo(), (effects::StereoLayout{effects::StereoMode::LeftRight, 180}));
}

}  // namespace
}  // namespace vdfx::app
