/// @file
/// @brief The editor with anchored effects (docs/anchors.md, "Anchors in evaluation"): the camera
/// turns 4 degrees right a frame, the exposure is anchored to the world. Placing a keyframe at
/// the view n at frame f stores q_f n; the preview, the grab and the selection work in the
/// world; the minimap, its dots, the track plot and the markers show the field and the keyframes
/// where they are at the playhead; the status says which frame a keyframe's direction is in; a
/// fixed flare light set "here" is fixed in the world. The document keeps the camera, the tracks
/// and every anchor, changes an anchor as one undoable edit, and refuses one naming no track.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "app/editor/editor.h"
#include "app/editor/visualizations.h"
#include "editor_test_util.h"
#include "io/input_error.h"
#include "io/sidecar_validate.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::Direction;
using effects::EffectType;
using test::looking;

constexpr std::int64_t kFrameNs = 33'333'333;
constexpr double kTurn = 4.0;  // degrees right a frame
const effects::Anchor kWorld{effects::Anchor::Kind::World, {}};

/// Where a direction of the video frame at frame f is in the world.
Direction world_of(const Direction& video, std::int64_t f) {
  return {effects::wrap_azimuth_deg(video.azimuth_deg + kTurn * static_cast<double>(f)),
          video.altitude_deg};
}
Direction video_of(const Direction& world, std::int64_t f) {
  return {effects::wrap_azimuth_deg(world.azimuth_deg - kTurn * static_cast<double>(f)),
          world.altitude_deg};
}

double angle_deg(const Direction& a, const Direction& b) {
  const Eigen::Vector3d u = effects::to_unit(a), v = effects::to_unit(b);
  return std::atan2(u.cross(v).norm(), u.dot(v)) * effects::kRadToDeg;
}

/// 90 frames, the camera turning kTurn degrees right a frame, an actor walking; the exposure
/// anchored to the world with one keyframe of 0 stops at world (-50, -5), frame 0.
io::Sidecar turning_sidecar() {
  io::Sidecar s = test::empty_sidecar(90);
  s.interpolation.time_scale = effects::kAuthorTimeScale;
  effects::CameraMotion camera;
  camera.source = effects::CameraMotion::Source::Given;
  for (int f = 0; f < 90; ++f)
    camera.orientation.push_back(effects::from_eigen(Eigen::Quaterniond(
        Eigen::AngleAxisd(-kTurn * f * effects::kDegToRad, Eigen::Vector3d::UnitY()))));
  s.camera = camera;
  effects::SubjectTrack actor{"actor", {}};
  for (int f = 0; f < 90; ++f) actor.points.push_back({f, {-20.0 + f, 0.0}, 1.0});
  s.tracks = {actor};
  s.effects.push_back({EffectType::Exposure, std::nullopt, {{{-50.0, -5.0}, 0, {0.0}}}, kWorld});
  return s;
}

class AnchoredEditor : public ::testing::Test {
 protected:
  AnchoredEditor() : ed_(turning_sidecar(), DocumentOptions{{.async = false}}, EditorOptions{}) {}
  void frame(double az, double alt, double squeeze = 0.0) {
    t_ += kFrameNs;
    xr::InputState in = looking(az, alt, t_);
    in.right.squeeze = squeeze;
    ed_.update(sync_.sync(in), t_);
  }
  const effects::Keyframe& key(std::size_t i) {
    return ed_.document().keyframes(EffectType::Exposure).at(i);
  }
  /// Places +2 stops looking at video (10, 5) at frame 30: world (130, 5).
  void place_at_30() {
    ed_.seek(30);
    frame(10.0, 5.0);
    ed_.set_chosen_params({2.0});
    ed_.place_keyframe();
  }
  Editor ed_;
  xr::ActionSync sync_;
  std::int64_t t_ = 0;
};

TEST_F(AnchoredEditor, PlacingStoresTheViewTurnedIntoTheWorldAtThePlayhead) {
  place_at_30();
  ASSERT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 2u);
  EXPECT_LT(angle_deg(key(1).direction, world_of({10.0, 5.0}, 30)), 1e-9)
      << key(1).direction.azimuth_deg << ", " << key(1).direction.altitude_deg;
  EXPECT_EQ(key(1).frame, 30);
  // Seen from anywhere in the clip, the keyframe's value is where the window of the world is.
  EXPECT_NEAR(ed_.params_for_view({10.0, 5.0}, 30).exposure_stops, 2.0, 1e-9);
  EXPECT_NEAR(ed_.params_for_view(video_of({130.0, 5.0}, 60), 60).exposure_stops, 2.0, 1e-9);
  EXPECT_LT(ed_.params_for_view({10.0, 5.0}, 60).exposure_stops, 1.5) << "the picture moved on";
  // What the status prints about a keyframe says its frame.
  ASSERT_TRUE(ed_.select_keyframe(1));
  EXPECT_NE(ed_.status_text().find("(world az 130 alt 5 frame 30)"), std::string::npos)
      << ed_.status_text();
  // Undo takes it away, redo puts it back where it was.
  ASSERT_TRUE(ed_.undo());
  EXPECT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 1u);
  ASSERT_TRUE(ed_.redo());
  EXPECT_LT(angle_deg(key(1).direction, world_of({10.0, 5.0}, 30)), 1e-9);
}

TEST_F(AnchoredEditor, ThePreviewIsPlacedInTheWorldAndShowsItsValuesAtTheView) {
  ed_.seek(30);
  frame(10.0, 5.0);
  ed_.set_chosen_params({1.5});
  ed_.begin_preview();
  ASSERT_TRUE(ed_.previewing());
  EXPECT_LT(angle_deg(ed_.document().pending()->key().direction, world_of({10.0, 5.0}, 30)), 1e-9);
  EXPECT_EQ(ed_.current_params().exposure_stops, 1.5);
  EXPECT_NEAR(ed_.params_for_view({10.0, 5.0}, 30).exposure_stops, 1.5, 1e-9);
}

TEST_F(AnchoredEditor, AHeldKeyframeFollowsTheViewInTheWorldAndStaysAtItsCentre) {
  place_at_30();
  const std::size_t steps = ed_.document().undo_stack().undo_size();
  frame(10.0, 5.0);
  frame(10.0, 5.0, 1.0);  // squeeze: selects the nearest (the one just placed) and holds it
  ASSERT_TRUE(ed_.grabbing());
  ASSERT_EQ(*ed_.selected_keyframe(), 1u);
  frame(30.0, 5.0, 1.0);  // turn 20 degrees right
  frame(30.0, 5.0, 0.0);  // let go
  EXPECT_LT(angle_deg(key(1).direction, world_of({30.0, 5.0}, 30)), 1e-6);
  // Held while the playhead moves on ten frames, looking at the same place of the picture: the
  // keyframe stays under the view, so its world direction turns with the camera.
  frame(30.0, 5.0, 1.0);
  ed_.seek(40);
  frame(30.0, 5.0, 1.0);
  frame(30.0, 5.0, 0.0);
  EXPECT_EQ(key(1).frame, 40);
  EXPECT_LT(angle_deg(key(1).direction, world_of({30.0, 5.0}, 40)), 1e-6);
  EXPECT_EQ(ed_.document().undo_stack().undo_size(), steps + 2);  // two moves
}

TEST_F(AnchoredEditor, VisualizationsShowTheFieldAndKeyframesWhereTheyAreAtThePlayhead) {
  place_at_30();
  frame(10.0, 5.0);
  const Visualizations& v = *ed_.view().visuals;
  ASSERT_EQ(v.dots.size(), 2u);
  EXPECT_LT(angle_deg(v.dots[1], {10.0, 5.0}), 1e-6) << "the dot where the keyframe is now";
  EXPECT_LT(angle_deg(v.dots[0], video_of({-50.0, -5.0}, 30)), 1e-6);
  // The minimap's brightest cell is at the keyframe as the video frame shows it now.
  ASSERT_TRUE(ed_.wait_for_visualizations(std::chrono::seconds(10)));
  const cv::Mat& field = ed_.minimap_field();
  cv::Point best;
  cv::minMaxLoc(field, nullptr, nullptr, nullptr, &best);
  const Direction peak = minimap_cell_direction(best.x, best.y, field.cols, field.rows);
  EXPECT_LT(angle_deg(peak, {10.0, 5.0}), 6.0) << peak.azimuth_deg << ", " << peak.altitude_deg;
  // The keyframe is near the view now, not once the camera has turned away.
  EXPECT_NE(std::find(ed_.near_keyframes().begin(), ed_.near_keyframes().end(), 1u),
            ed_.near_keyframes().end());
  ed_.seek(75);  // 180 degrees on
  frame(10.0, 5.0);
  EXPECT_EQ(std::find(ed_.near_keyframes().begin(), ed_.near_keyframes().end(), 1u),
            ed_.near_keyframes().end());
  // The track plot follows the view's direction of the video frame at every frame: at frame 30
  // it looked at the keyframe.
  const auto& frames = ed_.track_frames();
  const auto at30 = std::find(frames.begin(), frames.end(), 30) - frames.begin();
  ASSERT_LT(at30, static_cast<std::ptrdiff_t>(frames.size()));
  EXPECT_NEAR(ed_.track_values()[static_cast<std::size_t>(at30)], 2.0, 1e-6);
}

TEST_F(AnchoredEditor, SelectionAndJumpsMeasureInTheWorld) {
  place_at_30();
  ed_.seek(75);
  frame(video_of({130.0, 5.0}, 75).azimuth_deg, 5.0);
  ASSERT_TRUE(ed_.select_nearest());
  EXPECT_EQ(*ed_.selected_keyframe(), 1u);
  ed_.seek(0);
  frame(0.0, 0.0);
  const auto look = ed_.jump_to_keyframe(+1);
  ASSERT_TRUE(look);
  EXPECT_EQ(ed_.frame(), 30);
  EXPECT_LT(angle_deg(*look, {10.0, 5.0}), 1e-6) << "where it shows at its frame";
}

TEST_F(AnchoredEditor, LightHereOnAWorldAnchoredFlareIsALightOfTheWorld) {
  ed_.document().set_anchor(EditTarget::flare(), kWorld);
  ed_.seek(20);
  frame(-30.0, 10.0);
  ed_.set_light_here();
  const effects::FlareEffect flare = ed_.document().flare();
  const auto* light = std::get_if<Direction>(&flare.light);
  ASSERT_NE(light, nullptr);
  EXPECT_LT(angle_deg(*light, world_of({-30.0, 10.0}, 20)), 1e-9);
}

TEST(AnchoredDocument, KeepsTheCameraTracksAndAnchorsByteForByte) {
  io::Sidecar s = turning_sidecar();
  effects::FlareEffect flare = Document::new_flare();
  flare.anchor = {effects::Anchor::Kind::Track, "actor"};
  flare.keyframes = {{{0.0, 0.0}, 0, {1.0}}};
  s.flares = {flare, flare};
  effects::GrainEffect grain;
  grain.anchor = kWorld;
  grain.keyframes = {{{10.0, 0.0}, 5, {0.5, 1.0}}};
  s.grains = {grain};
  const std::string text = io::format_sidecar(s);
  const io::SidecarReport read = io::validate_sidecar_text(text, "s.vdfx.json");
  ASSERT_TRUE(read.ok()) << read.to_string();
  const Document doc(*read.sidecar, DocumentOptions{{.async = false}});
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), text);
  EXPECT_EQ(doc.anchor(EditTarget::flare()), flare.anchor);
  EXPECT_FALSE(doc.anchor_frames(EditTarget::grain()).identity());
  EXPECT_TRUE(doc.anchor_frames(EffectType::Tint).identity());
}

TEST(AnchoredDocument, ChangingAnAnchorKeepsEachKeyframeWhereItShowsAndUndoes) {
  io::Sidecar s = turning_sidecar();
  s.effects[0].anchor = {};
  s.effects[0].keyframes.push_back({{40.0, 10.0}, 60, {1.0}});
  Document doc(s, DocumentOptions{{.async = false}});
  const std::string before = io::format_sidecar(doc.sidecar());
  doc.set_anchor(EffectType::Exposure, kWorld);
  EXPECT_EQ(doc.anchor(EffectType::Exposure), kWorld);
  const auto& ks = doc.keyframes(EffectType::Exposure);
  EXPECT_LT(angle_deg(ks[0].direction, {-50.0, -5.0}), 1e-9) << "q_0 is the identity";
  EXPECT_LT(angle_deg(ks[1].direction, world_of({40.0, 10.0}, 60)), 1e-9);
  EXPECT_NE(io::format_sidecar(doc.sidecar()).find("\"anchor\": \"world\""), std::string::npos);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), before);
  EXPECT_TRUE(doc.anchor_frames(EffectType::Exposure).identity());
  ASSERT_TRUE(doc.redo());
  EXPECT_FALSE(doc.anchor_frames(EffectType::Exposure).identity());
  try {
    doc.set_anchor(EffectType::Exposure, {effects::Anchor::Kind::Track, "nobody"});
    FAIL() << "an anchor naming no track";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("track:nobody"), std::string::npos) << e.what();
  }
  EXPECT_EQ(doc.anchor(EffectType::Exposure), kWorld);
}

}  // namespace
}  // namespace vdfx::app
