/// @file
/// @brief The editor's flare and grain (issues 12 and 13, editor parts): the document edits the
/// sidecar's first flare and first grain (keyframes, style, light) as undo steps and writes the
/// others back unchanged; the editor's "Set light here", auto light and style switches are one
/// undo step each; the editor client draws the edited flare and grain live.
#include <gtest/gtest.h>

#include "app/editor/document.h"
#include "app/editor/editor.h"
#include "app/window/editor_client.h"
#include "editor_test_util.h"
#include "io/sidecar.h"

namespace vdfx::app {
namespace {

using effects::AutoLight;
using effects::Direction;
using effects::FlareEffect;
using effects::FlareStyle;
using effects::GrainEffect;
using effects::GrainStyle;

constexpr DocumentOptions kSync{{.async = false}};

/// Two flares (the first headset with a fixed light, the second directional and auto) and two
/// grains, each with one keyframe.
io::Sidecar two_of_each() {
  io::Sidecar sc = test::empty_sidecar();
  FlareEffect a;
  a.style = FlareStyle::Headset;
  a.settings = effects::default_flare_settings(FlareStyle::Headset);
  a.light = Direction{10.0, 20.0};
  a.keyframes = {{{10.0, 20.0}, 0, {1.5}}};
  FlareEffect b;
  b.light = AutoLight{};
  b.settings.rings = 3;
  b.keyframes = {{{-90.0, 0.0}, 5, {0.5}}};
  sc.flares = {a, b};
  GrainEffect g1;
  g1.style = GrainStyle::Headset;
  g1.keyframes = {{{0.0, 0.0}, 0, {0.3, 1.0}}};
  GrainEffect g2;
  g2.style = GrainStyle::FreeCloud;
  g2.seed = 7;
  g2.keyframes = {{{45.0, 0.0}, 0, {0.8, 2.0}}};
  sc.grains = {g1, g2};
  return sc;
}

TEST(DocumentFlare, FirstKeyframeMakesADirectionalAutoFlareAndUndoRemovesIt) {
  Document doc(test::empty_sidecar(), kSync);
  EXPECT_TRUE(doc.sidecar().flares.empty());
  doc.add_keyframe(EditTarget::flare(), {{30.0, 10.0}, 0, {2.0}});
  const io::Sidecar s = doc.sidecar();
  ASSERT_EQ(s.flares.size(), 1u);
  EXPECT_EQ(s.flares[0].style, FlareStyle::Directional);
  EXPECT_TRUE(std::holds_alternative<AutoLight>(s.flares[0].light));
  ASSERT_EQ(s.flares[0].keyframes.size(), 1u);
  EXPECT_DOUBLE_EQ(s.flares[0].keyframes[0].params[0], 2.0);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.sidecar().flares.empty());
}

TEST(DocumentFlare, EditsTheFirstFlareAndKeepsTheSecondUnchanged) {
  const io::Sidecar before = two_of_each();
  Document doc(before, kSync);
  EXPECT_EQ(doc.keyframes(EditTarget::flare()).size(), 1u);
  doc.set_flare_style(FlareStyle::Directional);
  doc.set_flare_light(AutoLight{});
  doc.add_keyframe(EditTarget::flare(), {{-20.0, 0.0}, 10, {3.0}});
  io::Sidecar s = doc.sidecar();
  ASSERT_EQ(s.flares.size(), 2u);
  EXPECT_EQ(s.flares[0].style, FlareStyle::Directional);
  // The plane was at the headset default: it moves to the directional default.
  EXPECT_DOUBLE_EQ(s.flares[0].settings.plane_m,
                   effects::default_flare_settings(FlareStyle::Directional).plane_m);
  EXPECT_TRUE(std::holds_alternative<AutoLight>(s.flares[0].light));
  EXPECT_EQ(s.flares[0].keyframes.size(), 2u);
  EXPECT_EQ(s.flares[1], before.flares[1]);
  EXPECT_EQ(s.grains, before.grains);
  // Three undo steps give back the file as it was.
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(doc.undo()) << i;
  s = doc.sidecar();
  EXPECT_EQ(s.flares, before.flares);
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.flare().style, FlareStyle::Directional);
}

TEST(DocumentGrain, StyleAndKeyframesOfTheFirstGrainRoundTripThroughTheFile) {
  const io::Sidecar before = two_of_each();
  Document doc(before, kSync);
  doc.set_grain_style(GrainStyle::ObjectCloud);
  doc.add_keyframe(EditTarget::grain(), {{90.0, 0.0}, 30, {0.6, 3.0}});
  const auto dir = test::temp_dir("grain_round_trip");
  const auto path = dir / "g.vdfx.json";
  io::write_sidecar(path, doc.sidecar());
  const io::Sidecar back = io::read_sidecar(path);
  ASSERT_EQ(back.grains.size(), 2u);
  EXPECT_EQ(back.grains[0].style, GrainStyle::ObjectCloud);
  // The sphere was at the headset's default, so it takes object_cloud's (2 m), as a new file would.
  EXPECT_EQ(back.grains[0].settings.get(effects::GrainSetting::SphereM), 2.0);
  EXPECT_EQ(back.grains[0].keyframes.size(), 2u);
  EXPECT_EQ(back.grains[1], before.grains[1]);
  EXPECT_EQ(back.flares, before.flares);
  // Values beyond the ranges are clamped: intensity 0..1, size 0.25..4.
  doc.set_params(EditTarget::grain(), {5.0, 100.0});
  EXPECT_DOUBLE_EQ(doc.params(EditTarget::grain())[0], 1.0);
  EXPECT_DOUBLE_EQ(doc.params(EditTarget::grain())[1], 4.0);
}

class EditorFlare : public ::testing::Test {
 protected:
  EditorFlare() : ed_(test::empty_sidecar(), kSync, desktop()) { look(30.0, 10.0); }
  static EditorOptions desktop() {
    EditorOptions o;
    o.layout = PanelLayout::Desktop;
    return o;
  }
  void look(double az, double alt) {
    t_ += 33'333'333;
    ed_.update(sync_.sync(test::looking(az, alt, t_)), t_);
  }
  Editor ed_;
  xr::ActionSync sync_;
  std::int64_t t_ = 0;
};

TEST_F(EditorFlare, SetLightHereIsOneUndoStepAtTheViewCentre) {
  ed_.select_effect(EditTarget::flare());
  EXPECT_TRUE(ed_.current_effect().is_flare());
  const std::size_t steps = ed_.document().undo_stack().undo_size();
  ed_.set_light_here();
  EXPECT_EQ(ed_.document().undo_stack().undo_size(), steps + 1);
  const FlareEffect flare = ed_.document().flare();
  const auto* fixed = std::get_if<Direction>(&flare.light);
  ASSERT_NE(fixed, nullptr);
  EXPECT_NEAR(fixed->azimuth_deg, 30.0, 1e-6);
  EXPECT_NEAR(fixed->altitude_deg, 10.0, 1e-6);
  EXPECT_NE(ed_.status_text().find("light"), std::string::npos) << ed_.status_text();
  ASSERT_TRUE(ed_.document().undo());
  EXPECT_TRUE(std::holds_alternative<AutoLight>(ed_.document().flare().light));
}

TEST_F(EditorFlare, AutoLightOffFixesTheLightWhereTheViewIsAndOnFindsItAgain) {
  ed_.select_effect(EditTarget::flare());
  look(-60.0, 5.0);
  ed_.set_auto_light(false);
  const FlareEffect flare = ed_.document().flare();
  const auto* fixed = std::get_if<Direction>(&flare.light);
  ASSERT_NE(fixed, nullptr);
  EXPECT_NEAR(fixed->azimuth_deg, -60.0, 1e-6);
  ed_.set_auto_light(true);
  EXPECT_TRUE(std::holds_alternative<AutoLight>(ed_.document().flare().light));
  ed_.set_flare_style(FlareStyle::Headset);
  EXPECT_EQ(ed_.document().flare().style, FlareStyle::Headset);
  EXPECT_DOUBLE_EQ(ed_.document().flare().settings.plane_m, 0.05);
}

TEST_F(EditorFlare, PlacedFlareKeyframeCarriesTheWidgetsIntensity) {
  ed_.select_effect(EditTarget::flare());
  ed_.set_chosen_params({2.5});
  ed_.place_keyframe();
  const auto& keys = ed_.document().keyframes(EditTarget::flare());
  ASSERT_EQ(keys.size(), 1u);
  EXPECT_NEAR(keys[0].direction.azimuth_deg, 30.0, 1e-6);
  EXPECT_DOUBLE_EQ(keys[0].params[0], 2.5);
  // The stack's parameters do not carry the flare: they stay neutral.
  EXPECT_DOUBLE_EQ(ed_.current_params().exposure_stops, 0.0);
  EXPECT_DOUBLE_EQ(ed_.current_params().blur_sigma_deg, 0.0);
}

TEST_F(EditorFlare, GrainStyleSwitchAndKeyframe) {
  ed_.select_effect(EditTarget::grain());
  ed_.set_grain_style(GrainStyle::FreeCloud);
  ed_.set_chosen_params({0.7, 2.0});
  ed_.place_keyframe();
  const io::Sidecar s = ed_.document().sidecar();
  ASSERT_EQ(s.grains.size(), 1u);
  EXPECT_EQ(s.grains[0].style, GrainStyle::FreeCloud);
  ASSERT_EQ(s.grains[0].keyframes.size(), 1u);
  EXPECT_DOUBLE_EQ(s.grains[0].keyframes[0].params[1], 2.0);
}

TEST_F(EditorFlare, ClientDrawsTheFlareNearItsLightAndNotAwayFromIt) {
  EditorClient client(ed_, nullptr);
  ed_.select_effect(EditTarget::flare());
  ed_.set_light_here();  // at (30, 10)
  ed_.set_chosen_params({2.0});
  ed_.place_keyframe();
  FrameInfo info;
  const auto frame = [&] {
    t_ += 33'333'333;
    client.update(sync_.sync(test::looking(30.0, 10.0, t_)), t_, info);
  };
  frame();
  const auto at = [](double az, double alt) {
    return xr::Pose{{0.0, 1.6, 0.0}, xr::look_rotation(az, alt)};
  };
  const auto near = client.flares(at(32.0, 10.0), 0, nullptr);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_GT(near[0].fade, 0.5);
  EXPECT_GT(near[0].intensity, 1.0);
  const auto away = client.flares(at(150.0, 0.0), 0, nullptr);
  EXPECT_TRUE(away.empty() || away[0].fade == 0.0);
  // Grain: none before a grain keyframe, one layer after (the layers follow the document at the
  // client's next update).
  EXPECT_TRUE(client.grains(at(0.0, 0.0), 0, 0).empty());
  ed_.select_effect(EditTarget::grain());
  ed_.set_chosen_params({0.5, 1.0});
  ed_.place_keyframe();
  frame();
  const auto g = client.grains(at(0.0, 0.0), 0, 0);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_GT(g[0].params.intensity, 0.1);
}

}  // namespace
}  // namespace vdfx::app
