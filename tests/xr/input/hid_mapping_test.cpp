/// @file
/// @brief The default HID mapping: sticks turn the head at the documented rate, buttons reach
/// their action paths, lost devices go neutral, the SpaceMouse steers head or hand.
#include "xr/input/hid_mapping.h"

#include <gtest/gtest.h>

#include <ostream>

#include "hid_test_data.h"
#include "input_test_util.h"

namespace vdfx::xr {
namespace {

using test_util::altitude_deg;
using test_util::azimuth_deg;
constexpr std::int64_t kSecond = 1'000'000'000;
const std::string kDs4 = "054c:05c4";
const std::string kSpace = "046d:c626";

TEST(HidMapping, LeftStickTurnsTheHeadAtTheLookRate) {
  HidInputMapper m;
  m.on_report(0, kDs4, test_data::ds4_report({{1, 0xFF}}));  // full right
  EXPECT_NEAR(azimuth_deg(m.state(kSecond / 2).head), 45.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(m.state(kSecond).head), 90.0, 1e-9);
  m.on_report(kSecond, kDs4, test_data::ds4_report({{2, 0x00}}));  // full up
  EXPECT_NEAR(altitude_deg(m.state(kSecond + kSecond / 2).head), 45.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(m.state(kSecond + kSecond / 2).head), 90.0, 1e-9);
  // Keeps pitching up to the limit, never over the pole.
  const double alt = altitude_deg(m.state(5 * kSecond).head);
  EXPECT_LE(alt, 89.0 + 1e-9);
  EXPECT_GT(alt, 85.0);
}

TEST(HidMapping, SmallDeflectionsInsideTheDeadzoneDoNothing) {
  HidInputMapper m;
  m.on_report(0, kDs4, test_data::ds4_report({{1, 0x88}, {3, 0x88}}));  // 8/127 = 0.063
  const InputState s = m.state(kSecond);
  EXPECT_NEAR(azimuth_deg(s.head), 0.0, 1e-12);
  EXPECT_EQ(s.right.thumbstick.x, 0.0);
}

TEST(HidMapping, StickRoleLeftThumbstickKeepsTheHeadStill) {
  HidMappingConfig cfg;
  cfg.left_stick = LeftStickRole::LeftThumbstick;
  HidInputMapper m(cfg);
  m.on_report(0, kDs4, test_data::ds4_report({{1, 0xFF}}));
  const InputState s = m.state(kSecond);
  EXPECT_NEAR(azimuth_deg(s.head), 0.0, 1e-12);
  EXPECT_NEAR(s.left.thumbstick.x, 1.0, 1e-12);
}

struct ButtonRow {
  const char* name;
  int byte;
  std::uint8_t bits;
  const char* path;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const ButtonRow& c, std::ostream* os) {
  *os << c.name;
}

// DS4 bits (see hid_parsers_test) -> the action they drive (docs/input.md).
const ButtonRow kButtons[] = {
    {"cross_a", 5, 0x28, "/user/hand/right/input/a/click"},
    {"circle_b", 5, 0x48, "/user/hand/right/input/b/click"},
    {"square_x", 5, 0x18, "/user/hand/left/input/x/click"},
    {"triangle_y", 5, 0x88, "/user/hand/left/input/y/click"},
    {"options_menu", 6, 0x20, "/user/hand/left/input/menu/click"},
    {"l3_left_click", 6, 0x40, "/user/hand/left/input/thumbstick/click"},
    {"r3_right_click", 6, 0x80, "/user/hand/right/input/thumbstick/click"},
    {"r1_right_squeeze", 6, 0x02, "/user/hand/right/input/squeeze/value"},
    {"l1_left_squeeze", 6, 0x01, "/user/hand/left/input/squeeze/value"},
    {"r2_right_trigger", 9, 0xFF, "/user/hand/right/input/trigger/value"},
    {"l2_left_trigger", 8, 0xFF, "/user/hand/left/input/trigger/value"},
    {"dpad_up_left_stick_y", 5, 0x00, "/user/hand/left/input/thumbstick/y"},
    {"dpad_left_left_stick_x", 5, 0x06, "/user/hand/left/input/thumbstick/x"},
};

double as_number(const ActionValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
  return std::abs(std::get<double>(v));
}

class Buttons : public ::testing::TestWithParam<ButtonRow> {};
TEST_P(Buttons, ReachTheirAction) {
  const ButtonRow& r = GetParam();
  HidInputMapper m;
  m.on_report(0, kDs4, test_data::ds4_report());
  ASSERT_TRUE(get_action(m.state(1), r.path));
  EXPECT_EQ(as_number(*get_action(m.state(1), r.path)), 0.0);
  m.on_report(2, kDs4, test_data::ds4_report({{r.byte, r.bits}}));
  EXPECT_EQ(as_number(*get_action(m.state(3), r.path)), 1.0);
}
INSTANTIATE_TEST_SUITE_P(Rows, Buttons, ::testing::ValuesIn(kButtons),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(HidMapping, LostDeviceGoesNeutralAndKeepsTheHead) {
  HidInputMapper m;
  m.on_report(0, kDs4, test_data::ds4_report({{1, 0xFF}, {9, 0xFF}, {5, 0x28}}));
  InputState s = m.state(kSecond);
  EXPECT_EQ(s.right.trigger, 1.0);
  EXPECT_TRUE(s.right.primary);
  m.on_report(kSecond, kDs4, std::vector<std::uint8_t>{});  // an empty report: device lost
  s = m.state(2 * kSecond);
  EXPECT_EQ(s.right.trigger, 0.0);
  EXPECT_FALSE(s.right.primary);
  EXPECT_NEAR(azimuth_deg(s.head), 90.0, 1e-9);  // turned until the loss, then stopped
}

TEST(HidMapping, RightAimFollowsTheView) {
  HidInputMapper m;
  m.on_report(0, kDs4, test_data::ds4_report({{1, 0xFF}}));
  const InputState s = m.state(kSecond / 3);
  EXPECT_NEAR(test_util::angle_deg(s.right.aim, s.head), 0.0, 1e-9);
  EXPECT_TRUE(s.left.tracked && s.right.tracked && s.head_tracked);
}

TEST(HidMapping, SpaceMouseTwistTurnsTheHeadRight) {
  HidInputMapper m;  // target head, 120 deg/s
  // Device z points down: a positive twist about it is clockwise seen from above: turn right.
  m.on_report(0, kSpace, test_data::spacemouse_report(2, 0, 0, 350));
  EXPECT_NEAR(azimuth_deg(m.state(kSecond / 2).head), 60.0, 1e-9);
  m.on_report(kSecond / 2, kSpace, test_data::spacemouse_report(2, 0, 0, 0));
  EXPECT_NEAR(azimuth_deg(m.state(kSecond).head), 60.0, 1e-9);
  m.on_report(kSecond, kSpace, std::vector<std::uint8_t>{0x03, 0x01});  // button 1: right trigger
  EXPECT_EQ(m.state(kSecond).right.trigger, 1.0);
}

TEST(HidMapping, SpaceMouseCanSteerTheRightHand) {
  HidMappingConfig cfg;
  cfg.spacemouse = SpaceMouseTarget::RightHand;
  HidInputMapper m(cfg);
  const glm::dvec3 start = m.state(0).right.aim.position;
  // Push the cap forward (device -y, away from the user): the hand moves along -z at 0.5 m/s.
  m.on_report(0, kSpace, test_data::spacemouse_report(1, 0, -350, 0));
  const InputState s = m.state(kSecond);
  EXPECT_NEAR(s.right.aim.position.z - start.z, -0.5, 1e-9);
  EXPECT_NEAR(azimuth_deg(s.head), 0.0, 1e-12);
}

TEST(HidMapping, GenericGamepadNeedsItsDescriptor) {
  HidInputMapper m;
  const auto report = test_data::generic_report(0x80, 0x80, 0xFF, 0x80, 0x0F, 0x001);
  EXPECT_FALSE(m.knows("0079:0006"));
  EXPECT_FALSE(m.on_report(0, "0079:0006", report));
  m.on_descriptor("0079:0006", test_data::kGenericGamepadDescriptor);
  EXPECT_TRUE(m.on_report(1, "0079:0006", report));
  const InputState s = m.state(2);
  EXPECT_NEAR(s.right.thumbstick.x, 1.0, 1e-4);
  EXPECT_TRUE(s.right.primary);
}

TEST(HidMapping, DeadzoneIsRadialAndRescaled) {
  EXPECT_EQ(apply_deadzone({0.1, 0.0}, 0.12), glm::dvec2(0.0, 0.0));
  EXPECT_NEAR(apply_deadzone({0.56, 0.0}, 0.12).x, 0.5, 1e-12);
  EXPECT_NEAR(glm::length(apply_deadzone({1.0, 1.0}, 0.12)), 1.0, 1e-12);
}

}  // namespace
}  // namespace vdfx::xr
