/// @file
/// @brief Panel wiring: the sim's mouse pointer on the desktop layout's panels -> editor commands.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

EditorOptions desktop() {
  EditorOptions o;
  o.layout = PanelLayout::Desktop;
  return o;
}

class PanelWiring : public ::testing::Test {
 protected:
  PanelWiring()
      : sim_(xr::create_sim_backend({})),
        ed_(test::empty_sidecar(test::kClipFrames), DocumentOptions{{.async = false}}, desktop()) {
    step();
  }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i, t_ += test::kFrameNs) ed_.update(sim_->poll(t_), t_);
  }
  void move(glm::dvec2 p) {
    sim_->push_event(xr::MouseMoveEvent{p.x, p.y});
    step();
  }
  void button(bool down) {
    sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, down});
    step(2);
  }
  void click(glm::dvec2 p) {
    move(p);
    button(true);
    button(false);
  }
  glm::dvec2 at(const char* panel, const char* widget) {
    return test::widget_cursor(panel, widget, test::kClipFrames);
  }

  std::unique_ptr<xr::InputBackend> sim_;
  Editor ed_;
  std::int64_t t_ = 0;
};

TEST_F(PanelWiring, PanelsAreInsideTheSimView) {
  for (auto* p : ed_.panels())
    for (const glm::dvec2 corner : {glm::dvec2(0, 0), glm::dvec2(p->width_px(), p->height_px())}) {
      const glm::dvec2 c = test::cursor_for(p->id(), corner, test::kClipFrames);
      EXPECT_GT(c.x, 0.0) << p->id();
      EXPECT_LT(c.x, 1280.0) << p->id();
      EXPECT_GT(c.y, 0.0) << p->id();
      EXPECT_LT(c.y, 720.0) << p->id();
    }
}

TEST_F(PanelWiring, MenuRowsSelectEveryEffect) {
  const ui::MenuList* menu = &ed_.ui().menu();
  ASSERT_EQ(static_cast<int>(menu->items().size()), EditTarget::kCount);
  for (int item = 0; item < EditTarget::kCount; ++item) {
    const ui::Rect r = menu->cell(item);
    click(test::cursor_for(kEffectPanelId, {r.x + r.w / 2, r.y + r.h / 2}));
    EXPECT_EQ(ed_.current_effect().index(), item) << menu->items()[static_cast<std::size_t>(item)];
  }
}

TEST_F(PanelWiring, SliderDragIsOneUndoStepAndUndoButtonRevertsIt) {
  auto* s = dynamic_cast<const ui::Slider1D*>(&ed_.ui().effect_widget(EffectType::Exposure));
  const double y = s->rect().y + s->rect().h / 2;
  auto px = [&](double v) {
    return test::cursor_for(
        kEffectPanelId, {s->track_x0() + (v + 8.0) / 16.0 * (s->track_x1() - s->track_x0()), y});
  };
  move(px(0.0));
  button(true);
  for (double v : {0.5, 1.0, 2.0, 3.0}) move(px(v));
  button(false);
  EXPECT_NEAR(ed_.document().params(EffectType::Exposure)[0], 3.0, 1e-9);
  EXPECT_EQ(ed_.document().undo_stack().undo_size(), 1u);
  EXPECT_FALSE(ed_.previewing());  // the trigger went to the UI
  EXPECT_TRUE(ed_.document().keyframes(EffectType::Exposure).empty());
  click(at(kEffectPanelId, "undo"));
  EXPECT_EQ(ed_.document().params(EffectType::Exposure)[0], 0.0);
  EXPECT_NEAR(s->get(), 0.0, 1e-12);  // the widget shows the restored value (to a few ulps)
  click(at(kEffectPanelId, "redo"));
  EXPECT_NEAR(ed_.document().params(EffectType::Exposure)[0], 3.0, 1e-9);
}

TEST_F(PanelWiring, TimelineScrubPlayAndToggles) {
  const ui::TimelineStrip* strip = &ed_.ui().strip();
  click(test::cursor_for(kTimelinePanelId, {strip->x_of(45), strip->rect().y + strip->rect().h / 2},
                         test::kClipFrames));
  EXPECT_EQ(ed_.frame(), 45);
  click(at(kTimelinePanelId, "play"));
  EXPECT_TRUE(ed_.playing());
  step(10);
  EXPECT_GT(ed_.frame(), 45);
  click(at(kTimelinePanelId, "play"));
  EXPECT_FALSE(ed_.playing());
  click(at(kViewsPanelId, "show_minimap"));
  EXPECT_FALSE(ed_.ui().minimap_toggle().on());
  EXPECT_EQ(ed_.ui().minimap().rect().w, 0.0);
  click(at(kViewsPanelId, "lock"));
  EXPECT_EQ(ed_.ui().placement(kTimelinePanelId).anchor, Anchor::World);
}

TEST_F(PanelWiring, VignettePadAndTintWheelSetTheChosenValues) {
  ed_.select_effect(EffectType::Vignette);
  step();
  auto* pad = dynamic_cast<const ui::Pad2D*>(&ed_.ui().effect_widget(EffectType::Vignette));
  const ui::Rect a = pad->area();
  click(test::cursor_for(kEffectPanelId, {a.x + a.w / 3.0, a.y + a.h / 2.0}));
  const auto& v = ed_.document().params(EffectType::Vignette);
  EXPECT_NEAR(v[0], 60.0, 1.0);
  EXPECT_NEAR(v[1], 90.0, 1.0);
  ed_.select_effect(EffectType::Tint);
  step();
  auto* wheel = dynamic_cast<const ui::ColourWheel*>(&ed_.ui().effect_widget(EffectType::Tint));
  click(test::cursor_for(kEffectPanelId,
                         wheel->disc_centre() + glm::dvec2(0.5 * wheel->disc_radius(), 0.0)));
  const auto& g = ed_.document().params(EffectType::Tint);
  EXPECT_GT(g[0], g[1]);  // hue 0 is red
  EXPECT_NEAR(0.25 * g[0] + 0.5 * g[1] + 0.25 * g[2], 1.0, 1e-9);
}

TEST_F(PanelWiring, TriggerOnAPanelDoesNotPlace) {
  // The trigger aimed through the cursor (the left mouse button; Space aims at the view centre
  // and places there wherever the cursor rests, issue 23).
  move(at(kEffectPanelId, "title"));
  sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
  step(3);
  EXPECT_FALSE(ed_.previewing());
  sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
  step(2);
  EXPECT_TRUE(ed_.document().keyframes(EffectType::Exposure).empty());
  move({640.0, 200.0});
  sim_->push_event(xr::KeyEvent{xr::Key::Space, true});
  step(2);
  EXPECT_TRUE(ed_.previewing());
  sim_->push_event(xr::KeyEvent{xr::Key::Space, false});
  step(2);
  EXPECT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 1u);
}

}  // namespace
}  // namespace vdfx::app
