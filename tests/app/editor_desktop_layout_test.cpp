/// @file
/// @brief The Desktop layout at the default window: panels cover exactly their window rectangles,
/// textures match their on-screen size (crisp text), the smallest text is at least 13 px tall, the
/// view centre stays clear; the heads-up line and expiring messages.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "ui/theme.h"
#include "xr/input/input_backend.h"
#include "xr/render/mirror.h"

namespace vdfx::app {
namespace {

EditorOptions desktop(DesktopViewport v = {}) {
  EditorOptions o;
  o.layout = PanelLayout::Desktop;
  o.viewport = v;
  return o;
}

TEST(DesktopLayout, PanelsCoverTheirRectanglesWithTexturesAtScreenResolution) {
  Editor ed(test::empty_sidecar(90), DocumentOptions{{.async = false}}, desktop());
  xr::SimConfig sim;
  ed.update(xr::create_sim_backend(sim)->poll(0), 0);
  const auto g = xr::MirrorGeometry::from_profile(xr::load_hmd_profile("generic90"),
                                                  xr::MirrorMode::Desktop, 1, 1, 1280, 720, 100.0);
  const xr::Pose head = ed.input().head;
  for (ui::Panel* p : ed.panels()) {
    if (!p->visible()) continue;  // the track marker, until there is a track
    const ScreenRect r = ed.ui().screen_rect(p->id());
    // Its corners project onto the rectangle's corners (to a hundredth of a pixel) ...
    const auto tl = xr::mirror_pixel_of(g, head.inverse().transform(p->world_of_pixel({0.0, 0.0})));
    const auto br = xr::mirror_pixel_of(
        g, head.inverse().transform(p->world_of_pixel(
               {static_cast<double>(p->width_px()), static_cast<double>(p->height_px())})));
    ASSERT_TRUE(tl && br) << p->id();
    EXPECT_NEAR(tl->x, r.x, 0.01) << p->id();
    EXPECT_NEAR(tl->y, r.y, 0.01) << p->id();
    EXPECT_NEAR(br->x, r.x + r.w, 0.01) << p->id();
    EXPECT_NEAR(br->y, r.y + r.h, 0.01) << p->id();
    // ... inside the window, and its texture has that many pixels: one texel per screen pixel.
    EXPECT_GE(r.x, 0) << p->id();
    EXPECT_LE(r.x + r.w, 1280) << p->id();
    EXPECT_GE(r.y, 0) << p->id();
    EXPECT_LE(r.y + r.h, 720) << p->id();
    EXPECT_EQ(p->texture_width(), r.w) << p->id();
    EXPECT_EQ(p->texture_height(), r.h) << p->id();
    // The view centre, where keyframes are placed, stays clear.
    EXPECT_FALSE(640 >= r.x && 640 < r.x + r.w && 360 >= r.y && 360 < r.y + r.h) << p->id();
  }
  // The smallest text the toolkit draws is rasterised at >= 13 px at the default window.
  EXPECT_GE(std::lround(ui::Theme::dark().font_small * desktop_ui_scale({})), 13);
}

TEST(DesktopLayout, PanelsFollowTheWindow) {
  Editor ed(test::empty_sidecar(90), DocumentOptions{{.async = false}}, desktop());
  ed.set_viewport({1920, 1080, 100.0});
  const ScreenRect r = ed.ui().screen_rect(kTimelinePanelId);
  EXPECT_EQ(r.x + r.w, 1920 - 12);
  EXPECT_EQ(r.y + r.h, 1080 - 12);
  EXPECT_EQ(ed.ui().panel(kTimelinePanelId)->texture_width(), r.w);
  EXPECT_GT(desktop_ui_scale({1920, 1080, 100.0}), desktop_ui_scale({}));
}

TEST(DesktopLayout, HeadsUpLineAndExpiringMessages) {
  Editor ed(test::empty_sidecar(90), DocumentOptions{{.async = false}}, desktop());
  ed.set_loop_status(12.0, false);
  ed.update(test::looking(30.0, -5.0, 0), 0);
  ed.seek(45);
  ed.update(test::looking(30.0, -5.0, 1), 1);
  const std::string hud = ed.hud_text();
  for (const char* s :
       {"frame 45 / 90", "0:01.50", "az 30\u00b0 alt -5\u00b0", "Exposure (0 keyframes)", "12 fps"})
    EXPECT_NE(hud.find(s), std::string::npos) << s << " in " << hud;
  EXPECT_EQ(ed.ui().hud_line()->text(), hud);
  ed.place_keyframe();
  ed.update(test::looking(30.0, -5.0, 2), 2);
  EXPECT_EQ(ed.hud_message(), "placed a keyframe");
  const std::int64_t later = 2 + Editor::kMessageLifetimeNs + 1;
  ed.update(test::looking(30.0, -5.0, later), later);
  EXPECT_NE(ed.hud_message(), "placed a keyframe") << "messages expire";
  ed.set_loop_status(12.0, true);
  ed.update(test::looking(30.0, -5.0, later + 1), later + 1);
  EXPECT_EQ(ed.hud_message(), "loading the video\u2026");
}

TEST(DesktopLayout, SpacePlacesAtTheCentreWhereverThePointerRestsAClickPressesThePanel) {
  // Issue 23: the heads-up line says "click the view or Space: keyframe at the centre", but Space
  // with the mouse resting on a panel (even its empty part) pressed the panel and placed nothing.
  Editor ed(test::empty_sidecar(90), DocumentOptions{{.async = false}}, desktop());
  xr::SimConfig sim;
  sim.window_width = test::kScriptViewport.width;
  sim.window_height = test::kScriptViewport.height;
  sim.hfov_deg = test::kScriptViewport.hfov_deg;
  auto in = xr::create_sim_backend(sim);
  std::int64_t t = 0;
  auto frames = [&](int n) {
    for (int i = 0; i < n; ++i, t += 33'333'333) ed.update(in->poll(t), t);
  };
  frames(1);
  // Over the effect panel's empty bottom part, and over its middle (the widget).
  const ScreenRect r = ed.ui().screen_rect(kEffectPanelId);
  for (const glm::dvec2 at : {glm::dvec2(r.x + r.w * 0.5, r.y + r.h - 6.0),
                              glm::dvec2(r.x + r.w * 0.5, r.y + r.h * 0.5)}) {
    const std::size_t before = ed.document().keyframes(effects::EffectType::Exposure).size();
    in->push_event(xr::MouseMoveEvent{at.x, at.y});
    frames(2);
    in->push_event(xr::KeyEvent{xr::Key::Space, true});
    frames(4);
    EXPECT_TRUE(ed.previewing()) << "Space previews at the centre";
    in->push_event(xr::KeyEvent{xr::Key::Space, false});
    frames(2);
    const auto& keys = ed.document().keyframes(effects::EffectType::Exposure);
    ASSERT_EQ(keys.size(), before + 1) << "placed, with the pointer on the panel";
    EXPECT_NEAR(keys.back().direction.azimuth_deg, ed.view_direction().azimuth_deg, 1e-6);
    EXPECT_NEAR(keys.back().direction.altitude_deg, ed.view_direction().altitude_deg, 1e-6);
    EXPECT_EQ(ed.hud_message(), "placed a keyframe");
    // Turn a little, so that the next placement is a new keyframe, not a replacement.
    in->push_event(xr::MouseButtonEvent{xr::MouseButton::Right, true});
    in->push_event(xr::MouseMoveEvent{at.x + 40.0, at.y});
    in->push_event(xr::MouseButtonEvent{xr::MouseButton::Right, false});
    in->push_event(xr::MouseMoveEvent{at.x, at.y});
    frames(2);
  }
  // The left button over the panel still presses the panel: nothing placed.
  const std::size_t before = ed.document().keyframes(effects::EffectType::Exposure).size();
  in->push_event(xr::MouseMoveEvent{r.x + r.w * 0.5, r.y + r.h - 6.0});
  frames(1);
  in->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
  frames(3);
  EXPECT_FALSE(ed.previewing());
  in->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
  frames(2);
  EXPECT_EQ(ed.document().keyframes(effects::EffectType::Exposure).size(), before);
}

}  // namespace
}  // namespace vdfx::app
