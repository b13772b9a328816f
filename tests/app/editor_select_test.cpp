/// @file
/// @brief Selecting a keyframe other than the nearest: a press on its minimap dot (through the
/// sim's mouse pointer on the desktop layout) and the previous / next keyframe buttons select
/// it, shown as the ring, title and status; the squeeze then grabs the selected keyframe.
#include <gtest/gtest.h>

#include "app/editor/editor.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using effects::Keyframe;

/// Three exposure keyframes; the head looks at the middle one (the nearest).
io::Sidecar three_keyframes() {
  io::Sidecar sc = test::empty_sidecar(test::kClipFrames);
  sc.effects.push_back(
      {EffectType::Exposure,
       std::nullopt,
       {{{-120.0, 0.0}, 10, {-1.0}}, {{0.0, 0.0}, 20, {1.0}}, {{120.0, 30.0}, 40, {2.0}}}});
  return sc;
}

EditorOptions desktop() {
  EditorOptions o;
  o.layout = PanelLayout::Desktop;
  return o;
}

class SelectByPointing : public ::testing::Test {
 protected:
  SelectByPointing()
      : sim_(xr::create_sim_backend({})),
        ed_(three_keyframes(), DocumentOptions{{.async = false}}, desktop()) {
    step();
  }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i, t_ += test::kFrameNs) ed_.update(sim_->poll(t_), t_);
  }
  /// Trigger (left mouse) pressed and released at a pixel of the views panel (minimap and plot).
  void click_views(glm::dvec2 pixel) {
    const glm::dvec2 c = test::cursor_for(kViewsPanelId, pixel, test::kClipFrames);
    sim_->push_event(xr::MouseMoveEvent{c.x, c.y});
    step();
    sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
    step(2);
    sim_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
    step(2);
  }
  glm::dvec2 dot(std::size_t i) {
    return ed_.ui().minimap().to_pixel(ed_.document().keyframes(EffectType::Exposure)[i].direction);
  }

  std::unique_ptr<xr::InputBackend> sim_;
  Editor ed_;
  std::int64_t t_ = 0;
};

TEST_F(SelectByPointing, PressingAMinimapDotSelectsThatKeyframe) {
  ASSERT_FALSE(ed_.selected_keyframe());
  click_views(dot(2) + glm::dvec2(6.0, -5.0));  // a few pixels off the dot's centre
  ASSERT_EQ(ed_.selected_keyframe(), std::optional<std::size_t>(2)) << ed_.status_text();
  EXPECT_FALSE(ed_.previewing()) << "a press on the panel never previews";
  EXPECT_EQ(ed_.document().keyframes(EffectType::Exposure).size(), 3u) << "nothing placed";
  EXPECT_EQ(ed_.ui().minimap().selected(), 2) << "ringed";
  EXPECT_NE(ed_.ui().title().text().find("keyframe 3 of 3"), std::string::npos)
      << ed_.ui().title().text();
  EXPECT_NE(ed_.status_text().find("SELECTED keyframe 3/3 (az 120 alt 30 frame 40)"),
            std::string::npos)
      << ed_.status_text();
  // The widget shows its values.
  EXPECT_DOUBLE_EQ(
      dynamic_cast<const ui::Slider1D*>(&ed_.ui().effect_widget(EffectType::Exposure))->value().x,
      2.0);

  // A press on the map away from every dot keeps the selection; another dot moves it.
  const ui::Rect map = ed_.ui().minimap().map_area();
  click_views({map.x + 0.5 * map.w, map.y + 0.9 * map.h});
  EXPECT_EQ(ed_.selected_keyframe(), std::optional<std::size_t>(2));
  click_views(dot(0));
  EXPECT_EQ(ed_.selected_keyframe(), std::optional<std::size_t>(0));
  EXPECT_EQ(ed_.ui().minimap().selected(), 0);
  // Pressing the same dot again after deselecting selects it again.
  ed_.deselect();
  click_views(dot(0));
  EXPECT_EQ(ed_.selected_keyframe(), std::optional<std::size_t>(0));

  // The grab holds the selected keyframe, not the one nearest the view (index 1).
  ASSERT_TRUE(ed_.grab());
  EXPECT_EQ(ed_.selected_keyframe(), std::optional<std::size_t>(0));
  ASSERT_TRUE(ed_.selected_preview());
  EXPECT_EQ(ed_.selected_preview()->frame, 10);
}

TEST(MinimapPick, DotsArePickedWithinTheRadiusNearestFirst) {
  ui::Minimap m("minimap", "m");
  m.set_rect({0, 0, 1000, 600});
  EXPECT_FALSE(m.interactive()) << "nothing to pick";
  m.set_keyframes({{0.0, 0.0}, {3.0, 0.0}, {90.0, 45.0}});
  EXPECT_TRUE(m.interactive());
  const struct {
    glm::dvec2 offset;
    int from, expect;
  } cases[] = {
      {{0.0, 0.0}, 2, 2},
      {{ui::Minimap::kPickRadius - 1.0, 0.0}, 2, 2},
      {{0.0, ui::Minimap::kPickRadius + 1.0}, 2, -1},
      {{-1.0, 0.0}, 0, 0},  // two close dots: the nearer wins
      {{1.0, 0.0}, 1, 1},
  };
  for (const auto& c : cases) {
    const glm::dvec2 p = m.to_pixel(m.keyframes()[static_cast<std::size_t>(c.from)]) + c.offset;
    EXPECT_EQ(m.keyframe_at(p), c.expect)
        << "from " << c.from << " offset " << c.offset.x << "," << c.offset.y;
  }
  const glm::dvec2 before = m.value();
  m.click(m.to_pixel(m.keyframes()[2]));
  EXPECT_EQ(m.value().x, 2.0);
  EXPECT_NE(m.value(), before);
  m.click(m.to_pixel(m.keyframes()[2]));  // the same keyframe again still changes the value
  EXPECT_EQ(m.value().y, before.y + 2.0);
}

TEST(SelectByJump, PreviousAndNextSelectTheKeyframeTheyJumpTo) {
  Editor ed(three_keyframes(), DocumentOptions{{.async = false}}, EditorOptions{});
  ed.update(test::looking(0.0, 0.0), 0);
  ed.seek(25);
  ASSERT_TRUE(ed.jump_to_keyframe(+1));
  EXPECT_EQ(ed.frame(), 40);
  EXPECT_EQ(ed.selected_keyframe(), std::optional<std::size_t>(2));
  ed.update(test::looking(0.0, 0.0), 33'333'333);
  EXPECT_EQ(ed.ui().minimap().selected(), 2);
  EXPECT_NE(ed.status_text().find("SELECTED keyframe 3/3"), std::string::npos) << ed.status_text();
  ASSERT_TRUE(ed.jump_to_keyframe(-1));
  EXPECT_EQ(ed.frame(), 20);
  EXPECT_EQ(ed.selected_keyframe(), std::optional<std::size_t>(1));
  // While grabbing, a jump moves the playhead (the held keyframe follows it) and keeps the grab.
  ASSERT_TRUE(ed.grab());
  ASSERT_TRUE(ed.jump_to_keyframe(-1));
  EXPECT_TRUE(ed.grabbing());
  EXPECT_EQ(ed.selected_keyframe(), std::optional<std::size_t>(1));
  EXPECT_EQ(ed.selected_preview()->frame, 10);
}

}  // namespace
}  // namespace vdfx::app
