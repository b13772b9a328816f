/// @file
/// @brief The sim backend: key bindings (table), mouse look, aim through the cursor, left-handed
/// swap, and the bindings text.
#include <gtest/gtest.h>

#include <ostream>

#include "input_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::xr {
namespace {

using test_util::altitude_deg;
using test_util::angle_deg;
using test_util::azimuth_deg;

double value_at(const InputState& s, const std::string& path) {
  const auto v = get_action(s, path);
  EXPECT_TRUE(v.has_value()) << path;
  if (!v) return -99;
  if (const bool* b = std::get_if<bool>(&*v)) return *b ? 1.0 : 0.0;
  return std::get<double>(*v);
}

struct KeyRow {
  Key key;
  bool left_handed;
  const char* path;
  double pressed_value;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const KeyRow& c, std::ostream* os) {
  *os << key_name(c.key) << (c.left_handed ? " (left-handed)" : "") << " -> " << c.path;
}

const KeyRow kKeys[] = {
    {Key::Space, false, "/user/hand/right/input/trigger/value", 1.0},
    {Key::G, false, "/user/hand/right/input/squeeze/value", 1.0},
    {Key::J, false, "/user/hand/right/input/a/click", 1.0},
    {Key::K, false, "/user/hand/right/input/b/click", 1.0},
    {Key::L, false, "/user/hand/right/input/thumbstick/click", 1.0},
    {Key::Up, false, "/user/hand/right/input/thumbstick/y", 1.0},
    {Key::Down, false, "/user/hand/right/input/thumbstick/y", -1.0},
    {Key::Left, false, "/user/hand/right/input/thumbstick/x", -1.0},
    {Key::Right, false, "/user/hand/right/input/thumbstick/x", 1.0},
    {Key::E, false, "/user/hand/left/input/trigger/value", 1.0},
    {Key::Q, false, "/user/hand/left/input/squeeze/value", 1.0},
    {Key::X, false, "/user/hand/left/input/x/click", 1.0},
    {Key::Y, false, "/user/hand/left/input/y/click", 1.0},
    {Key::C, false, "/user/hand/left/input/thumbstick/click", 1.0},
    {Key::W, false, "/user/hand/left/input/thumbstick/y", 1.0},
    {Key::S, false, "/user/hand/left/input/thumbstick/y", -1.0},
    {Key::A, false, "/user/hand/left/input/thumbstick/x", -1.0},
    {Key::D, false, "/user/hand/left/input/thumbstick/x", 1.0},
    {Key::M, false, "/user/hand/left/input/menu/click", 1.0},
    {Key::Tab, false, "/user/hand/left/input/menu/click", 1.0},
    // Left-handed: the main keys drive the left hand, the others the right hand.
    {Key::Space, true, "/user/hand/left/input/trigger/value", 1.0},
    {Key::J, true, "/user/hand/left/input/x/click", 1.0},
    {Key::Up, true, "/user/hand/left/input/thumbstick/y", 1.0},
    {Key::E, true, "/user/hand/right/input/trigger/value", 1.0},
    {Key::X, true, "/user/hand/right/input/a/click", 1.0},
    {Key::D, true, "/user/hand/right/input/thumbstick/x", 1.0},
    {Key::M, true, "/user/hand/left/input/menu/click", 1.0},
};

class SimKeys : public ::testing::TestWithParam<KeyRow> {};

TEST_P(SimKeys, PressAndRelease) {
  const KeyRow& r = GetParam();
  SimConfig cfg;
  cfg.left_handed = r.left_handed;
  auto sim = create_sim_backend(cfg);
  EXPECT_EQ(value_at(sim->poll(0), r.path), 0.0);
  sim->push_event(KeyEvent{r.key, true});
  const InputState pressed = sim->poll(1);
  EXPECT_EQ(value_at(pressed, r.path), r.pressed_value);
  // Nothing else moved: every other path with a value stays neutral.
  for (const std::string& p : action_paths()) {
    const auto v = get_action(pressed, p);
    if (p == r.path || std::holds_alternative<Pose>(*v) || p.ends_with("tracked") ||
        p.ends_with("thumbstick"))
      continue;
    EXPECT_EQ(value_at(pressed, p), 0.0) << p << " moved with " << key_name(r.key);
  }
  sim->push_event(KeyEvent{r.key, false});
  EXPECT_EQ(value_at(sim->poll(2), r.path), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Rows, SimKeys, ::testing::ValuesIn(kKeys), [](const auto& i) {
  std::string n(key_name(i.param.key));
  n.erase(std::remove(n.begin(), n.end(), ' '), n.end());
  return n + (i.param.left_handed ? "_lefthanded" : "");
});

TEST(Sim, LeftMouseButtonIsTheMainTrigger) {
  auto sim = create_sim_backend({});
  sim->push_event(MouseButtonEvent{MouseButton::Left, true});
  EXPECT_EQ(sim->poll(1).right.trigger, 1.0);
  sim->push_event(MouseButtonEvent{MouseButton::Left, false});
  EXPECT_EQ(sim->poll(2).right.trigger, 0.0);
}

TEST(Sim, DiagonalStickStaysOnTheUnitCircle) {
  auto sim = create_sim_backend({});
  sim->push_event(KeyEvent{Key::W, true});
  sim->push_event(KeyEvent{Key::D, true});
  const InputState s = sim->poll(1);
  EXPECT_NEAR(s.left.thumbstick.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.left.thumbstick.y, std::sqrt(0.5), 1e-12);
}

struct LookRow {
  const char* name;
  LookMode mode;
  double dx, dy;             // the drag, pixels (y down)
  double azimuth, altitude;  // where the head looks afterwards, degrees
};
// Issue 23: desktop 360 players (YouTube, Facebook 360) drag the image: dragging left turns the
// view right and dragging down looks up. Mouselook is a game's camera, the other way round.
const LookRow kLook[] = {
    {"drag_right_up", LookMode::Drag, 100, -50, -20.0, -10.0},
    {"drag_left", LookMode::Drag, -100, 0, 20.0, 0.0},
    {"drag_down", LookMode::Drag, 0, 50, 0.0, 10.0},
    {"mouselook_right_up", LookMode::Mouselook, 100, -50, 20.0, 10.0},
    {"mouselook_left", LookMode::Mouselook, -100, 0, -20.0, 0.0},
};
void PrintTo(const LookRow& r, std::ostream* os) {
  *os << r.name;
}

class SimLook : public ::testing::TestWithParam<LookRow> {};
TEST_P(SimLook, RightDragTurnsTheHeadTheChosenWayAtTheDocumentedSensitivity) {
  const LookRow& r = GetParam();
  SimConfig cfg;
  cfg.look_deg_per_px = 0.2;  // a fixed rate (the default follows the cursor: below)
  cfg.look = r.mode;
  auto sim = create_sim_backend(cfg);
  sim->push_event(MouseMoveEvent{640, 360});
  sim->push_event(MouseButtonEvent{MouseButton::Right, true});
  sim->push_event(MouseMoveEvent{640 + r.dx, 360 + r.dy});
  InputState s = sim->poll(1);
  EXPECT_NEAR(azimuth_deg(s.head), r.azimuth, 1e-9);
  EXPECT_NEAR(altitude_deg(s.head), r.altitude, 1e-9);
  sim->push_event(MouseButtonEvent{MouseButton::Right, false});
  sim->push_event(MouseMoveEvent{100, 100});  // moving without the button: no turn
  s = sim->poll(2);
  EXPECT_NEAR(azimuth_deg(s.head), r.azimuth, 1e-9);
  EXPECT_NEAR(s.head.position.y, kDefaultEyeHeight, 1e-12);
}
INSTANTIATE_TEST_SUITE_P(Rows, SimLook, ::testing::ValuesIn(kLook),
                         [](const auto& i) { return std::string(i.param.name); });

// The default drag follows the cursor: what was under the cursor when the button went down is
// under it again after the drag, in a window of any size and field of view (at 0.2 degrees a
// pixel, the rate before, it ran ahead of the cursor by 2.5 times at 1920 pixels and 100 degrees).
TEST(Sim, TheDefaultDragKeepsThePointUnderTheCursorUnderIt) {
  for (const auto& [width, hfov] : {std::pair{1280, 100.0}, {1920, 100.0}, {800, 60.0}}) {
    auto sim = create_sim_backend({});
    sim->push_event(ViewGeometryEvent{width, width * 9 / 16, hfov});
    const double cx = width / 2.0, cy = width * 9 / 32.0;
    // The world direction under the view's centre: straight ahead (azimuth 0).
    sim->push_event(MouseMoveEvent{cx, cy});
    sim->push_event(MouseButtonEvent{MouseButton::Right, true});
    for (int i = 1; i <= 8; ++i) sim->push_event(MouseMoveEvent{cx + 5.0 * i, cy});
    sim->push_event(MouseButtonEvent{MouseButton::Right, false});
    const InputState s = sim->poll(1);
    // The pinhole's ray through the cursor, 40 pixels right of the centre, turned by the head.
    const double tan_h = std::tan(0.5 * hfov * 3.14159265358979323846 / 180.0);
    const glm::dvec3 ray =
        glm::normalize(glm::dvec3((2.0 * (cx + 40.0) / width - 1.0) * tan_h, 0.0, -1.0));
    const glm::dvec3 world = s.head.orientation * ray;
    const double az = std::atan2(world.x, -world.z) * 180.0 / 3.14159265358979323846;
    // One pixel at the edge of the drag spans a little less than at the centre: within a tenth
    // of a pixel's angle here, where 0.2 degrees a pixel would be 3 to 5 degrees off.
    EXPECT_NEAR(az, 0.0, 0.1 * look_deg_per_px_of(SimConfig{})) << width << " px, " << hfov;
  }
  SimConfig wide;
  wide.window_width = 2560;
  EXPECT_NEAR(look_deg_per_px_of(wide), 0.5 * look_deg_per_px_of(SimConfig{}), 1e-4);
  wide.look_deg_per_px = 0.2;
  EXPECT_EQ(look_deg_per_px_of(wide), 0.2) << "a rate set is kept";
}

TEST(Sim, DragIsTheDefaultAndTheKeyISwitchesTheLookDirection) {
  EXPECT_EQ(SimConfig{}.look, LookMode::Drag);
  auto sim = create_sim_backend({});
  auto drag_right = [&](double x0) {
    sim->push_event(MouseMoveEvent{x0, 360});
    sim->push_event(MouseButtonEvent{MouseButton::Right, true});
    sim->push_event(MouseMoveEvent{x0 + 50, 360});
    sim->push_event(MouseButtonEvent{MouseButton::Right, false});
  };
  const double turn = 50.0 * look_deg_per_px_of(SimConfig{});
  drag_right(600);
  EXPECT_NEAR(azimuth_deg(sim->poll(1).head), -turn, 1e-9);
  sim->push_event(KeyEvent{Key::I, true});
  sim->push_event(KeyEvent{Key::I, false});
  drag_right(600);
  EXPECT_NEAR(azimuth_deg(sim->poll(2).head), 0.0, 1e-9) << "mouselook turns back";
  sim->push_event(KeyEvent{Key::I, true});
  sim->push_event(KeyEvent{Key::I, false});
  drag_right(600);
  EXPECT_NEAR(azimuth_deg(sim->poll(3).head), -turn, 1e-9) << "and drag again";
  EXPECT_EQ(parse_look_mode("mouselook"), LookMode::Mouselook);
  EXPECT_EQ(parse_look_mode("drag"), LookMode::Drag);
  EXPECT_FALSE(parse_look_mode("invert").has_value());
  EXPECT_NE(sim_bindings_text(SimConfig{}).find("drag: as 360 players (left turns right)"),
            std::string::npos);
  SimConfig mouselook;
  mouselook.look = LookMode::Mouselook;
  EXPECT_NE(sim_bindings_text(mouselook).find("mouselook: as games"), std::string::npos);
}

TEST(Sim, SpaceAimsAtTheViewCentreWhereverTheCursorRestsAClickAtTheCursor) {
  // Issue 23: Space with the cursor resting on a panel pressed the panel (the ray went through
  // the cursor); Space is the keyboard's "place at the centre".
  auto sim = create_sim_backend({});
  sim->push_event(MouseMoveEvent{1200, 100});  // far off the centre, where a panel would be
  InputState s = sim->poll(1);
  EXPECT_GT(angle_deg(s.right.aim, s.head), 30.0);
  sim->push_event(KeyEvent{Key::Space, true});
  s = sim->poll(2);
  EXPECT_EQ(s.right.trigger, 1.0);
  EXPECT_NEAR(angle_deg(s.right.aim, s.head), 0.0, 1e-9) << "Space aims at the centre";
  sim->push_event(KeyEvent{Key::Space, false});
  s = sim->poll(3);
  EXPECT_EQ(s.right.trigger, 0.0);
  EXPECT_GT(angle_deg(s.right.aim, s.head), 30.0) << "back through the cursor";
  sim->push_event(MouseButtonEvent{MouseButton::Left, true});
  s = sim->poll(4);
  EXPECT_EQ(s.right.trigger, 1.0);
  EXPECT_GT(angle_deg(s.right.aim, s.head), 30.0) << "a click presses what is under the cursor";
}

TEST(Sim, PitchStopsShortOfThePoles) {
  SimConfig cfg;
  cfg.look = LookMode::Mouselook;
  auto sim = create_sim_backend(cfg);
  sim->push_event(MouseButtonEvent{MouseButton::Right, true});
  sim->push_event(MouseMoveEvent{640, -5000});
  EXPECT_NEAR(altitude_deg(sim->poll(1).head), 89.0, 1e-9);
  auto drag = create_sim_backend({});
  drag->push_event(MouseButtonEvent{MouseButton::Right, true});
  drag->push_event(MouseMoveEvent{640, -5000});
  EXPECT_NEAR(altitude_deg(drag->poll(1).head), -89.0, 1e-9);
}

struct CursorRow {
  const char* name;
  double x, y;
  double hfov;
  double expected_angle_deg;  // between the aim ray and the view's forward direction
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const CursorRow& c, std::ostream* os) {
  *os << c.name;
}

// 1280 x 720 window: tan(vfov/2) = tan(hfov/2) * 720 / 1280.
const CursorRow kCursor[] = {
    {"centre", 640, 360, 90, 0.0},
    {"right_edge", 1280, 360, 90, 45.0},
    {"left_edge_fov60", 0, 360, 60, 30.0},
    {"top_edge", 640, 0, 90, std::atan(720.0 / 1280.0) * test_util::kRadToDeg},
    {"corner", 1280, 720, 90,
     std::acos(1.0 / std::sqrt(1.0 + 1.0 + 0.5625 * 0.5625)) * test_util::kRadToDeg},
};

class SimCursor : public ::testing::TestWithParam<CursorRow> {};
TEST_P(SimCursor, AimRayGoesThroughTheCursor) {
  const CursorRow& r = GetParam();
  auto sim = create_sim_backend({});
  sim->push_event(ViewGeometryEvent{1280, 720, r.hfov});
  sim->push_event(MouseButtonEvent{MouseButton::Right, true});
  sim->push_event(MouseMoveEvent{740, 360});  // turn the head first: the aim is relative to it
  sim->push_event(MouseButtonEvent{MouseButton::Right, false});
  sim->push_event(MouseMoveEvent{r.x, r.y});
  const InputState s = sim->poll(1);
  EXPECT_NEAR(angle_deg(s.right.aim, s.head), r.expected_angle_deg, 1e-9);
  EXPECT_NEAR(glm::length(s.right.aim.position - s.head.position), 0.0,
              1e-12);  // ray starts at the eye
  // Right of centre aims right of the view, above aims up.
  const glm::dvec3 d = glm::inverse(s.head.orientation) * forward(s.right.aim);
  if (r.x > 640) {
    EXPECT_GT(d.x, 0.0);
  }
  if (r.x < 640) {
    EXPECT_LT(d.x, 0.0);
  }
  if (r.y < 360) {
    EXPECT_GT(d.y, 0.0);
  }
}
INSTANTIATE_TEST_SUITE_P(Rows, SimCursor, ::testing::ValuesIn(kCursor),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(Sim, LeftHandedMouseAimsTheLeftHand) {
  SimConfig cfg;
  cfg.left_handed = true;
  auto sim = create_sim_backend(cfg);
  sim->push_event(MouseMoveEvent{1280, 360});
  sim->push_event(MouseButtonEvent{MouseButton::Left, true});
  const InputState s = sim->poll(1);
  EXPECT_NEAR(angle_deg(s.left.aim, s.head), 0.5 * cfg.hfov_deg, 1e-9);  // the window's right edge
  EXPECT_EQ(s.left.trigger, 1.0);
  EXPECT_EQ(s.right.trigger, 0.0);
  EXPECT_GT(s.right.aim.position.x, s.head.position.x);  // the other hand rests on its own side
}

TEST(Sim, EventsApplyAtTheNextPollAndTimeIsStamped) {
  auto sim = create_sim_backend({});
  sim->push_event(KeyEvent{Key::Space, true});
  const InputState s = sim->poll(123456789);
  EXPECT_EQ(s.t_ns, 123456789);
  EXPECT_EQ(s.right.trigger, 1.0);
  EXPECT_TRUE(s.head_tracked && s.left.tracked && s.right.tracked);
}

TEST(Sim, BindingsTextListsEveryBinding) {
  const std::string text = sim_bindings_text({});
  for (const char* needle : {"right mouse button drag", "following the cursor (0.107 deg per pixel",
                             "Space", "/user/hand/right/input/trigger/value",
                             "/user/hand/right/input/a/click", "/user/hand/left/input/menu/click",
                             "/user/hand/left/input/thumbstick/y = +1", "Left arrow"}) {
    EXPECT_NE(text.find(needle), std::string::npos) << needle << "\n" << text;
  }
  SimConfig lh;
  lh.left_handed = true;
  const std::string left = sim_bindings_text(lh);
  EXPECT_NE(left.find("/user/hand/left/input/aim/pose"), std::string::npos) << left;
  EXPECT_EQ(left.find("/user/hand/right/input/aim/pose"), std::string::npos) << left;
}

TEST(Actions, EveryPathResolvesAndUnknownOnesDoNot) {
  InputState s = neutral_input_state(0);
  s.right.trigger = 0.75;
  s.left.thumbstick = {0.5, -0.25};
  s.left.menu = true;
  s.head.position = {1, 2, 3};
  EXPECT_EQ(action_paths().size(), 2u + 2u * 11u + 1u);
  for (const std::string& p : action_paths()) EXPECT_TRUE(get_action(s, p).has_value()) << p;
  EXPECT_EQ(std::get<double>(*get_action(s, "/user/hand/right/input/trigger/value")), 0.75);
  EXPECT_EQ(std::get<glm::dvec2>(*get_action(s, "/user/hand/left/input/thumbstick")),
            glm::dvec2(0.5, -0.25));
  EXPECT_EQ(std::get<double>(*get_action(s, "/user/hand/left/input/thumbstick/y")), -0.25);
  EXPECT_TRUE(std::get<bool>(*get_action(s, "/user/hand/left/input/menu/click")));
  EXPECT_EQ(std::get<Pose>(*get_action(s, "/user/head/pose")).position, glm::dvec3(1, 2, 3));
  EXPECT_FALSE(get_action(s, "/user/hand/right/input/menu/click"));  // no menu on the right
  EXPECT_FALSE(get_action(s, "/user/hand/left/input/a/click"));
  EXPECT_FALSE(get_action(s, "/user/head"));
}

TEST(Actions, LookRotationFollowsTheContractDirections) {
  EXPECT_NEAR(forward(Pose{{}, look_rotation(90, 0)}).x, 1.0, 1e-12);  // azimuth +90 is +x
  EXPECT_NEAR(forward(Pose{{}, look_rotation(0, 90)}).y, 1.0, 1e-12);  // altitude +90 is up
  EXPECT_NEAR(forward(Pose{{}, look_rotation(0, 0)}).z, -1.0, 1e-12);  // forward is -z
}

}  // namespace
}  // namespace vdfx::xr
