/// @file
/// @brief Ray hit testing, pointer states, drags, trigger edges, thumbstick, events; panel dirty
/// tracking and placement. No GL context anywhere.
#include "ui/interaction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <ostream>

#include "sample_panels.h"
#include "ui/button.h"
#include "ui/menu_list.h"
#include "ui/slider.h"

namespace vdfx::ui::test {
namespace {

const glm::dvec3 kEye{0.0, 1.5, 0.0};

struct Scene {
  std::unique_ptr<Panel> panel = make_effect_panel();
  std::vector<Panel*> panels{panel.get()};
  Pointer pointer;
  bool trigger_down = false;  //!< the edges' level before this step
  Scene() { panel->set_world_pose({{0.0, 1.5, -1.0}, glm::dquat(1, 0, 0, 0)}); }
  Ray ray_to(glm::dvec2 pixel) const { return {kEye, panel->world_of_pixel(pixel) - kEye}; }
  Ray ray_to(const std::string& widget, glm::dvec2 offset = {0, 0}) const {
    return ray_to(panel->find(widget)->rect().centre() + offset);
  }
  /// The trigger as a button with its edges (the caller's edge detector, here a plain level).
  ButtonEdges edges(double trigger) {
    const bool down = trigger > 0.5;
    const ButtonEdges e{down, down && !trigger_down, !down && trigger_down};
    trigger_down = down;
    return e;
  }
  std::vector<Event> step(const Ray& r, double trigger, glm::dvec2 stick = {0, 0},
                          double dt = 1.0 / 72) {
    return pointer.update(panels, {r, edges(trigger), stick}, dt);
  }
};

/// A widget's id, "" for none.
std::string id_of(const Widget* w) {
  return w ? w->id() : std::string();
}

std::vector<EventKind> kinds(const std::vector<Event>& ev) {
  std::vector<EventKind> k;
  for (const auto& e : ev) k.push_back(e.kind);
  return k;
}

// Rays at known angles: the panel (0.25 m wide, 1 m ahead) spans +-7.125 deg horizontally.
struct AngleCase {
  const char* name;
  double yaw_deg, pitch_deg;
  bool hits;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const AngleCase& c, std::ostream* os) {
  *os << c.name;
}
const AngleCase kAngles[] = {
    {"centre", 0, 0, true},   {"left_inside", -7.0, 0, true},  {"right_outside", 7.3, 0, false},
    {"above", 0, 7.3, false}, {"below_inside", 0, -7.0, true}, {"behind_viewer", 180, 0, false},
};

class RayAngle : public ::testing::TestWithParam<AngleCase> {};
TEST_P(RayAngle, HitsOnlyWithinBounds) {
  Scene s;
  const double yaw = GetParam().yaw_deg * std::numbers::pi / 180;
  const double pitch = GetParam().pitch_deg * std::numbers::pi / 180;
  const glm::dvec3 dir{std::tan(yaw), std::tan(pitch), -1.0};
  const glm::dvec3 d = GetParam().yaw_deg == 180 ? glm::dvec3(0, 0, 1) : dir;
  const auto hit = hit_panels(s.panels, {kEye, d});
  EXPECT_EQ(hit.has_value(), GetParam().hits);
  if (hit && GetParam().yaw_deg == 0 && GetParam().pitch_deg == 0) {
    EXPECT_NEAR(hit->pixel.x, 500.0, 1e-9);
    EXPECT_NEAR(hit->pixel.y, 500.0, 1e-9);
    EXPECT_NEAR(hit->distance, 1.0, 1e-12);
  }
}
INSTANTIATE_TEST_SUITE_P(Table, RayAngle, ::testing::ValuesIn(kAngles),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(HitTest, RaysHitKnownWidgets) {
  Scene s;
  for (const char* id : {"undo", "redo", "exposure", "effect_menu", "world_lock"}) {
    s.step(s.ray_to(id), 0.0);
    EXPECT_EQ(id_of(s.pointer.hovered()), id);
    EXPECT_TRUE(s.panel->find(id)->hovered());
  }
  s.step(s.ray_to("title"), 0.0);  // labels are not interactive
  EXPECT_EQ(id_of(s.pointer.hovered()), "");
  EXPECT_FALSE(s.panel->find("world_lock")->hovered());
}

TEST(HitTest, BackFacingPanelIsMissed) {
  Scene s;
  // Turned around (faces -z): the viewer sees its back.
  s.panel->set_world_pose({{0, 1.5, -1.0}, glm::angleAxis(std::numbers::pi, glm::dvec3(0, 1, 0))});
  EXPECT_FALSE(hit_panels(s.panels, {kEye, {0, 0, -1}}).has_value());
  const auto plane = intersect_panel_plane(*s.panel, {kEye, {0, 0, -1}});
  ASSERT_TRUE(plane.has_value());
  EXPECT_FALSE(plane->front);
  EXPECT_TRUE(plane->inside);
}

TEST(HitTest, NearestFrontFacingPanelWins) {
  auto near = make_effect_panel(), far = make_timeline_panel();
  near->set_world_pose({{0, 1.5, -0.8}, {}});
  far->set_world_pose({{0, 1.5, -1.5}, {}});
  std::vector<Panel*> both{far.get(), near.get()};
  auto hit = hit_panels(both, {kEye, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->panel, near.get());
  near->set_visible(false);
  EXPECT_EQ(hit_panels(both, {kEye, {0, 0, -1}})->panel, far.get());
  near->set_visible(true);
  near->set_world_pose({{0, 1.5, -0.8}, glm::angleAxis(std::numbers::pi, glm::dvec3(0, 1, 0))});
  EXPECT_EQ(hit_panels(both, {kEye, {0, 0, -1}})->panel, far.get());
}

TEST(HitTest, TiltedPanelMapsPixelsThroughItsPose) {
  Scene s;
  const glm::dquat tilt = glm::angleAxis(0.4, glm::normalize(glm::dvec3(1, 1, 0)));
  s.panel->set_world_pose({{0.1, 1.4, -0.9}, tilt});
  for (glm::dvec2 px : {glm::dvec2(100, 900), glm::dvec2(640, 210)}) {
    const auto hit = hit_panels(s.panels, s.ray_to(px));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->pixel.x, px.x, 1e-6);
    EXPECT_NEAR(hit->pixel.y, px.y, 1e-6);
  }
}

TEST(Pointer, ClickNeedsPressAndReleaseOnTheSameWidget) {
  Scene s;
  s.step(s.ray_to("undo"), 0.0);
  EXPECT_TRUE(s.step(s.ray_to("undo"), 0.9).empty());
  EXPECT_TRUE(s.panel->find("undo")->pressed());
  auto ev = s.step(s.ray_to("undo"), 0.0);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].widget, "undo");
  EXPECT_EQ(ev[0].panel, "effects");
  EXPECT_EQ(ev[0].kind, EventKind::Clicked);
  // Pressed on undo, released on redo: nothing.
  s.step(s.ray_to("undo"), 0.9);
  EXPECT_TRUE(s.step(s.ray_to("redo"), 0.0).empty());
  EXPECT_FALSE(s.panel->find("undo")->pressed());
}

TEST(Pointer, ToggleAndMenuReportValueChanges) {
  Scene s;
  s.step(s.ray_to("world_lock"), 0.9);
  auto ev = s.step(s.ray_to("world_lock"), 0.0);
  ASSERT_EQ(kinds(ev), (std::vector{EventKind::Clicked, EventKind::ValueChanged}));
  EXPECT_EQ(ev[1].old_value.x, 0.0);
  EXPECT_EQ(ev[1].new_value.x, 1.0);
  auto* menu = s.panel->find_as<MenuList>("effect_menu");
  const Rect r = menu->rect();
  const glm::dvec2 row5{r.centre().x, r.y + 8 + 76 * 5 + 30};  // "Vignette"
  s.step(s.ray_to(row5), 0.9);
  ev = s.step(s.ray_to(row5), 0.0);
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[1].old_value.x, 2.0);
  EXPECT_EQ(ev[1].new_value.x, 5.0);
  EXPECT_EQ(menu->selected(), 5);
}

// The pointer takes the trigger's edges as given: a level without a press edge presses nothing,
// and a tap (pressed in one update, released in the next) clicks.
TEST(Pointer, ActsOnTheTriggerEdgesItIsGiven) {
  Scene s;
  Pointer& p = s.pointer;
  const Ray undo = s.ray_to("undo");
  EXPECT_TRUE(p.update(s.panels, {undo, {true, false, false}}, 0.0).empty());
  EXPECT_EQ(p.pressed(), nullptr) << "down, but no press edge";
  p.update(s.panels, {undo, {true, true, false}}, 0.0);
  EXPECT_EQ(id_of(p.pressed()), "undo");
  const auto ev = p.update(s.panels, {undo, {false, false, true}}, 0.0);
  ASSERT_EQ(kinds(ev), std::vector{EventKind::Clicked});
  EXPECT_EQ(p.pressed(), nullptr);
}

TEST(Pointer, DragMovesSliderMonotonicallyAndBracketsTheGesture) {
  Scene s;
  auto* sl = s.panel->find_as<Slider1D>("exposure");
  const double y = sl->rect().centre().y;
  std::vector<Event> all;
  const double x0 = sl->track_x0() + 10;
  for (int i = 0; i <= 40; ++i) {
    const double x = x0 + i * 30.0;  // ends well past the right edge of the panel
    auto ev = s.step(s.ray_to(glm::dvec2(std::min(x, 2000.0), y)), 1.0);
    all.insert(all.end(), ev.begin(), ev.end());
  }
  auto ev = s.step(s.ray_to(glm::dvec2(900, y)), 0.0);
  all.insert(all.end(), ev.begin(), ev.end());
  ASSERT_GE(all.size(), 3u);
  EXPECT_EQ(all.front().kind, EventKind::DragBegin);
  // The press jumps to the pressed point near the left end; from there on values only grow.
  ASSERT_EQ(all[1].kind, EventKind::ValueChanged);
  EXPECT_EQ(all[1].old_value.x, 1.5);
  EXPECT_LT(all[1].new_value.x, -7.0);
  double last = all[1].new_value.x;
  int changes = 0;
  for (size_t i = 2; i < all.size(); ++i) {
    if (all[i].kind != EventKind::ValueChanged) continue;
    EXPECT_EQ(all[i].old_value.x, last);
    EXPECT_GT(all[i].new_value.x, last);
    last = all[i].new_value.x;
    ++changes;
  }
  EXPECT_GT(changes, 10);
  EXPECT_DOUBLE_EQ(sl->get(), 8.0);  // followed the ray past the panel edge and clamped
  const auto end = std::find_if(all.begin(), all.end(),
                                [](const Event& e) { return e.kind == EventKind::DragEnd; });
  ASSERT_NE(end, all.end());
  EXPECT_EQ(end->old_value.x, all.front().new_value.x);
  EXPECT_EQ(end->new_value.x, 8.0);
}

TEST(Pointer, ThumbstickPushStepsOnceThenMovesAtATimeBasedRate) {
  // The pointer rests on a button (not focusable): the stick acts on the focused slider.
  auto run = [](double dt, int frames) {
    Scene s;
    s.step(s.ray_to("exposure", {0, 200}), 0.0);  // aim below it: a press there is elsewhere
    s.step(s.ray_to("exposure"), 0.0);
    s.step(s.ray_to("exposure"), 1.0);
    s.step(s.ray_to("exposure"), 0.0);
    EXPECT_EQ(id_of(s.pointer.focused()), "exposure");
    auto* sl = s.panel->find_as<Slider1D>("exposure");
    sl->set_value(0.0);
    std::vector<Event> all;
    for (int i = 0; i < frames; ++i) {
      auto ev = s.step(s.ray_to("undo"), 0.0, {1.0, 0.0}, dt);
      all.insert(all.end(), ev.begin(), ev.end());
    }
    auto ev = s.step(s.ray_to("undo"), 0.0, {0.0, 0.0}, dt);
    all.insert(all.end(), ev.begin(), ev.end());
    EXPECT_EQ(all.front().kind, EventKind::DragBegin);
    EXPECT_EQ(all.back().kind, EventKind::DragEnd);
    return sl->get();
  };
  // A tap (one frame) is exactly one step, at any frame time.
  EXPECT_NEAR(run(0.1, 1), 0.1, 1e-12);
  EXPECT_NEAR(run(0.3, 1), 0.1, 1e-12);
  // Held: one step, then the range sweeps in kStickSweepSeconds past the repeat delay.
  const double delay = PointerSettings{}.stick_repeat_delay_s;
  for (const auto& [dt, frames] : {std::pair{0.1, 15}, std::pair{0.025, 60}}) {
    const double moving = (frames - 1) * dt - delay;
    EXPECT_NEAR(run(dt, frames), 0.1 + 16.0 / kStickSweepSeconds * moving, 0.1 + 1e-9) << dt;
  }
}

TEST(Pointer, ThumbstickActsOnTheHoveredWidget) {
  // No click first: the slider under the pointer takes the stick (the sim's arrow keys).
  Scene s;
  auto* sl = s.panel->find_as<Slider1D>("exposure");
  sl->set_value(0.0);
  s.step(s.ray_to("exposure"), 0.0, {0.0, 0.0}, 0.05);
  EXPECT_TRUE(s.pointer.focused() == nullptr);
  s.step(s.ray_to("exposure"), 0.0, {-1.0, 0.0}, 0.05);
  s.step(s.ray_to("exposure"), 0.0, {0.0, 0.0}, 0.05);
  EXPECT_NEAR(sl->get(), -0.1, 1e-12);
}

TEST(Pointer, FineDragMovesATenthOfThePointerWithoutJumps) {
  Scene s;
  auto* sl = s.panel->find_as<Slider1D>("exposure");
  sl->set_value(0.0);
  const double per_px = 16.0 / (sl->track_x1() - sl->track_x0());  // stops per panel pixel
  const glm::dvec2 thumb = *sl->drag_point();
  const auto fine = [&](glm::dvec2 p, double trigger, bool on) {
    return s.pointer.update(s.panels, {s.ray_to(p), s.edges(trigger), {0.0, 0.0}, on}, 1.0 / 72);
  };
  // A fine press away from the thumb keeps the value; 200 px of motion move it by 20 px' worth.
  const glm::dvec2 press = thumb + glm::dvec2(150.0, 0.0);
  fine(press, 0.0, true);
  fine(press, 1.0, true);
  EXPECT_NEAR(sl->get(), 0.0, 1e-12);
  fine(press + glm::dvec2(200.0, 0.0), 1.0, true);
  EXPECT_NEAR(sl->get(), 20.0 * per_px, 0.05 + 1e-9);  // snapped to the 0.1 step
  const double at_fine = sl->get();
  // Shift released mid-drag: no jump, then the pointer's own motion again.
  fine(press + glm::dvec2(200.0, 0.0), 1.0, false);
  EXPECT_NEAR(sl->get(), at_fine, 1e-12);
  fine(press + glm::dvec2(230.0, 0.0), 1.0, false);
  EXPECT_NEAR(sl->get(), at_fine + 30.0 * per_px, 0.05 + 1e-9);
  fine(press + glm::dvec2(230.0, 0.0), 0.0, false);
}

TEST(Pointer, ThumbstickStepsMenuWithRepeat) {
  Scene s;
  auto* menu = s.panel->find_as<MenuList>("effect_menu");
  menu->select(0);
  const glm::dvec2 row0{menu->rect().centre().x, menu->rect().y + 40};
  s.step(s.ray_to(row0), 1.0);
  s.step(s.ray_to(row0), 0.0);
  ASSERT_EQ(id_of(s.pointer.focused()), "effect_menu");
  const double dt = 0.05;
  const int frames = 20;  // 1 s held down
  for (int i = 0; i < frames; ++i) s.step(s.ray_to(row0), 0.0, {0.0, -1.0}, dt);
  // One row at once, then one every period once held past the repeat delay.
  const double moving = (frames - 1) * dt - PointerSettings{}.stick_repeat_delay_s;
  const int repeats = static_cast<int>(std::floor(moving / MenuList::kRepeatSeconds + 1e-9));
  EXPECT_EQ(menu->selected(), std::min(5, 1 + repeats));
}

TEST(Panel, RerendersOnlyWhenSomethingChanged) {
  auto p = make_effect_panel();
  EXPECT_TRUE(p->dirty());
  p->texture();
  p->texture();
  EXPECT_EQ(p->render_count(), 1);
  auto* sl = p->find_as<Slider1D>("exposure");
  sl->set_value(sl->get());  // same value: nothing to draw
  EXPECT_FALSE(p->render_if_dirty());
  sl->set_value(3.0);
  EXPECT_TRUE(p->dirty());
  p->texture();
  EXPECT_EQ(p->render_count(), 2);
  p->find("undo")->set_hovered(true);
  EXPECT_TRUE(p->render_if_dirty());
  EXPECT_FALSE(p->render_if_dirty());
  EXPECT_EQ(p->render_count(), 3);
}

TEST(Panel, HoverSweepRerendersOncePerChange) {
  Scene s;
  s.panel->texture();
  const int before = s.panel->render_count();
  for (int i = 0; i < 5; ++i) {
    s.step(s.ray_to("undo"), 0.0);
    s.panel->render_if_dirty();
  }
  EXPECT_EQ(s.panel->render_count(), before + 1);  // hover on undo, then steady
}

TEST(Panel, AttachedToHandFollowsThenLocksInWorld) {
  auto p = make_effect_panel();
  const Pose world{{0.3, 1.2, -0.5}, glm::angleAxis(0.3, glm::dvec3(0, 1, 0))};
  p->set_world_pose(world);
  const Pose grip{{0.2, 1.0, -0.3}, glm::angleAxis(-0.5, glm::dvec3(1, 0, 0))};
  p->attach_keeping_pose(grip);
  p->update_hand(grip);
  EXPECT_NEAR(glm::length(p->pose().position - world.position), 0.0, 1e-12);
  const Pose moved{{0.5, 1.1, -0.2}, glm::angleAxis(0.7, glm::dvec3(0, 0, 1)) * grip.orientation};
  p->update_hand(moved);
  const glm::dvec3 expected = moved.transform(grip.inverse().transform(world.position));
  EXPECT_NEAR(glm::length(p->pose().position - expected), 0.0, 1e-12);
  const Pose locked = p->pose();
  p->lock_in_world();
  p->update_hand(grip);
  EXPECT_FALSE(p->attached_to_hand());
  EXPECT_NEAR(glm::length(p->pose().position - locked.position), 0.0, 1e-15);
}

}  // namespace
}  // namespace vdfx::ui::test
