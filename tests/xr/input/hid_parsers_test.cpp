/// @file
/// @brief Report parsers against hand-checked reports (one row per case).
#include "xr/input/hid_parsers.h"

#include <gtest/gtest.h>

#include <ostream>

#include "hid_test_data.h"

namespace vdfx::xr {
namespace {

using test_data::Edits;
using P = PadButton;

struct PadCase {
  const char* name;
  std::vector<std::pair<int, std::uint8_t>> edits;
  std::array<double, 2> left, right;
  double lt, rt;
  std::vector<PadButton> pressed;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const PadCase& c, std::ostream* os) {
  *os << c.name;
}

void expect_pad(const GamepadState& s, const PadCase& c) {
  EXPECT_NEAR(s.left_stick[0], c.left[0], 1e-12);
  EXPECT_NEAR(s.left_stick[1], c.left[1], 1e-12);
  EXPECT_NEAR(s.right_stick[0], c.right[0], 1e-12);
  EXPECT_NEAR(s.right_stick[1], c.right[1], 1e-12);
  EXPECT_NEAR(s.left_trigger, c.lt, 1e-12);
  EXPECT_NEAR(s.right_trigger, c.rt, 1e-12);
  GamepadState expected;
  for (PadButton b : c.pressed) expected.set(b, true);
  EXPECT_EQ(s.buttons, expected.buttons) << "got " << s.buttons << " want " << expected.buttons;
}

std::vector<std::uint8_t> apply_edits(std::vector<std::uint8_t> r,
                                      const std::vector<std::pair<int, std::uint8_t>>& e) {
  for (auto [i, v] : e) r[i] = v;
  return r;
}

// DualShock 4 USB report 0x01: 1-4 sticks, 5 hat + square/cross/circle/triangle, 6 L1 R1 L2 R2
// share options L3 R3, 7 PS touchpad counter, 8 L2 analog, 9 R2 analog.
const PadCase kDs4[] = {
    {"rest", {}, {0, 0}, {0, 0}, 0, 0, {}},
    {"left_stick_right_up", {{1, 0xFF}, {2, 0x00}}, {1, 1}, {0, 0}, 0, 0, {}},
    {"right_stick_left_down", {{3, 0x00}, {4, 0xFF}}, {0, 0}, {-1, -1}, 0, 0, {}},
    {"half_right", {{1, 0xC0}}, {64.0 / 127.0, 0}, {0, 0}, 0, 0, {}},
    {"triggers",
     {{8, 0xFF}, {9, 0x80}, {6, 0x0C}},
     {0, 0},
     {0, 0},
     1.0,
     128.0 / 255.0,
     {P::L2, P::R2}},
    {"face_buttons", {{5, 0xF8}}, {0, 0}, {0, 0}, 0, 0, {P::West, P::South, P::East, P::North}},
    {"cross_only", {{5, 0x28}}, {0, 0}, {0, 0}, 0, 0, {P::South}},
    {"hat_north_east", {{5, 0x01}}, {0, 0}, {0, 0}, 0, 0, {P::DpadUp, P::DpadRight}},
    {"hat_south_west", {{5, 0x05}}, {0, 0}, {0, 0}, 0, 0, {P::DpadDown, P::DpadLeft}},
    {"hat_west", {{5, 0x06}}, {0, 0}, {0, 0}, 0, 0, {P::DpadLeft}},
    {"shoulders_meta",
     {{6, 0xF3}, {7, 0x03 | 0xFC}},
     {0, 0},
     {0, 0},
     0,
     0,
     {P::L1, P::R1, P::Select, P::Start, P::L3, P::R3, P::Home, P::Touchpad}},
};

class Ds4 : public ::testing::TestWithParam<PadCase> {};
TEST_P(Ds4, Parses) {
  const auto s = parse_ds4_usb_report(apply_edits(test_data::ds4_report(), GetParam().edits));
  ASSERT_TRUE(s.has_value());
  expect_pad(*s, GetParam());
}
INSTANTIATE_TEST_SUITE_P(Rows, Ds4, ::testing::ValuesIn(kDs4),
                         [](const auto& i) { return std::string(i.param.name); });

// DualSense USB report 0x01: 1-4 sticks, 5 L2, 6 R2, 7 sequence, 8-10 buttons as the DS4's 5-7.
const PadCase kDualSense[] = {
    {"rest_with_sequence", {{7, 0x42}}, {0, 0}, {0, 0}, 0, 0, {}},
    {"sticks", {{1, 0x00}, {2, 0xFF}, {3, 0xFF}, {4, 0x00}}, {-1, -1}, {1, 1}, 0, 0, {}},
    {"triggers", {{5, 0x33}, {6, 0xFF}}, {0, 0}, {0, 0}, 0x33 / 255.0, 1.0, {}},
    {"triangle_and_hat_south", {{8, 0x84}}, {0, 0}, {0, 0}, 0, 0, {P::North, P::DpadDown}},
    {"create_options_ps",
     {{9, 0x30}, {10, 0x01}},
     {0, 0},
     {0, 0},
     0,
     0,
     {P::Select, P::Start, P::Home}},
    {"l1_r3", {{9, 0x81}}, {0, 0}, {0, 0}, 0, 0, {P::L1, P::R3}},
};

class DualSense : public ::testing::TestWithParam<PadCase> {};
TEST_P(DualSense, Parses) {
  const auto s =
      parse_dualsense_usb_report(apply_edits(test_data::dualsense_report(), GetParam().edits));
  ASSERT_TRUE(s.has_value());
  expect_pad(*s, GetParam());
}
INSTANTIATE_TEST_SUITE_P(Rows, DualSense, ::testing::ValuesIn(kDualSense),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(SonyReports, RejectOtherIdsAndShortReports) {
  auto bt = test_data::ds4_report();
  bt[0] = 0x11;  // Bluetooth report: not parsed
  EXPECT_FALSE(parse_ds4_usb_report(bt));
  EXPECT_FALSE(parse_ds4_usb_report(std::vector<std::uint8_t>{0x01, 0x80, 0x80}));
  EXPECT_FALSE(parse_dualsense_usb_report(std::vector<std::uint8_t>(10, 0x01)));
}

struct SpaceMouseCase {
  const char* name;
  std::vector<std::vector<std::uint8_t>> reports;
  std::array<double, 3> t, r;
  std::uint32_t buttons;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const SpaceMouseCase& c, std::ostream* os) {
  *os << c.name;
}

const SpaceMouseCase kSpaceMouse[] = {
    {"translation", {test_data::spacemouse_report(1, 350, -350, 0)}, {1, -1, 0}, {0, 0, 0}, 0},
    {"rotation", {test_data::spacemouse_report(2, 175, 0, -175)}, {0, 0, 0}, {0.5, 0, -0.5}, 0},
    {"translation_then_rotation",
     {test_data::spacemouse_report(1, 35, 70, -105), test_data::spacemouse_report(2, 0, 350, 0)},
     {0.1, 0.2, -0.3},
     {0, 1, 0},
     0},
    {"clamped_beyond_full_scale",
     {test_data::spacemouse_report(1, 1000, -1000, 0)},
     {1, -1, 0},
     {0, 0, 0},
     0},
    {"buttons", {{0x03, 0x03}}, {0, 0, 0}, {0, 0, 0}, 3},
    {"buttons_released", {{0x03, 0x02}, {0x03, 0x00}}, {0, 0, 0}, {0, 0, 0}, 0},
};

class SpaceMouse : public ::testing::TestWithParam<SpaceMouseCase> {};
TEST_P(SpaceMouse, Parses) {
  SpaceMouseState s;
  for (const auto& r : GetParam().reports) ASSERT_TRUE(apply_spacemouse_report(s, r));
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(s.translation[i], GetParam().t[i], 1e-12) << i;
    EXPECT_NEAR(s.rotation[i], GetParam().r[i], 1e-12) << i;
  }
  EXPECT_EQ(s.buttons, GetParam().buttons);
}
INSTANTIATE_TEST_SUITE_P(Rows, SpaceMouse, ::testing::ValuesIn(kSpaceMouse),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(SpaceMouse, CombinedTwelveByteReportCarriesAllSixAxes) {
  auto r = test_data::spacemouse_report(1, 350, 0, -175);
  const auto rot = test_data::spacemouse_report(2, 0, 35, 350);
  r.insert(r.end(), rot.begin() + 1, rot.end());
  ASSERT_EQ(r.size(), 13u);
  SpaceMouseState s;
  ASSERT_TRUE(apply_spacemouse_report(s, r));
  EXPECT_NEAR(s.translation[0], 1.0, 1e-12);
  EXPECT_NEAR(s.translation[2], -0.5, 1e-12);
  EXPECT_NEAR(s.rotation[1], 0.1, 1e-12);
  EXPECT_NEAR(s.rotation[2], 1.0, 1e-12);
  EXPECT_FALSE(apply_spacemouse_report(s, std::vector<std::uint8_t>{0x04, 0x00}));
}

struct GenericCase {
  const char* name;
  std::vector<std::uint8_t> report;
  std::array<double, 2> left, right;
  std::vector<PadButton> pressed;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const GenericCase& c, std::ostream* os) {
  *os << c.name;
}

const GenericCase kGeneric[] = {
    {"rest_hat_released",
     test_data::generic_report(0x80, 0x80, 0x80, 0x80, 0x0F, 0),
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {}},
    {"left_full_left_up",
     test_data::generic_report(0x00, 0x00, 0x80, 0x80, 0x0F, 0),
     {-1, 1},
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {}},
    {"right_stick_is_z_rz",
     test_data::generic_report(0x80, 0x80, 0xFF, 0xFF, 0x0F, 0),
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {1, -1},
     {}},
    {"hat_up_buttons_1_12",
     test_data::generic_report(0x80, 0x80, 0x80, 0x80, 0, 0x801),
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {P::DpadUp, P::South, P::R3}},
    {"buttons_2_to_5_hat_east",
     test_data::generic_report(0x80, 0x80, 0x80, 0x80, 2, 0x1E),
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {2 * 128 / 255.0 - 1, -(2 * 128 / 255.0 - 1)},
     {P::DpadRight, P::East, P::West, P::North, P::L1}},
};

class Generic : public ::testing::TestWithParam<GenericCase> {};
TEST_P(Generic, DecodesThroughTheDescriptor) {
  HidReportParser p(HidDeviceKind::GenericGamepad, test_data::kGenericGamepadDescriptor);
  ASSERT_TRUE(p.apply(GetParam().report));
  expect_pad(p.gamepad(),
             {GetParam().name, {}, GetParam().left, GetParam().right, 0, 0, GetParam().pressed});
}
INSTANTIATE_TEST_SUITE_P(Rows, Generic, ::testing::ValuesIn(kGeneric),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(Generic, ReportIdsUpdateOnlyTheirFields) {
  HidReportParser p(HidDeviceKind::GenericGamepad, test_data::kReportIdGamepadDescriptor);
  ASSERT_TRUE(p.apply(std::vector<std::uint8_t>{0x01, 0x00, 0x80, 0xFF, 0x7F}));
  EXPECT_NEAR(p.gamepad().left_stick[0], -1.0, 1e-12);
  EXPECT_NEAR(p.gamepad().left_stick[1], -1.0, 1e-12);  // HID +Y is down
  ASSERT_TRUE(
      p.apply(std::vector<std::uint8_t>{0x02, 0x05, 0x00, 0x03}));  // buttons 1, 3; hat 3 = E
  EXPECT_NEAR(p.gamepad().left_stick[0], -1.0, 1e-12);              // kept from report 1
  EXPECT_TRUE(p.gamepad().pressed(P::South));
  EXPECT_TRUE(p.gamepad().pressed(P::West));
  EXPECT_FALSE(p.gamepad().pressed(P::East));
  EXPECT_TRUE(p.gamepad().pressed(P::DpadRight));
  ASSERT_TRUE(p.apply(std::vector<std::uint8_t>{0x02, 0x00, 0x00, 0x00}));  // hat 0: released
  EXPECT_FALSE(p.gamepad().pressed(P::DpadRight));
  EXPECT_FALSE(p.apply(std::vector<std::uint8_t>{0x07, 0x00}));  // unknown report ID
}

TEST(Generic, RxRyAreTheRightStickAndZRzTheTriggersWhenPresent) {
  HidReportParser p(HidDeviceKind::GenericGamepad, test_data::kXboxStyleDescriptor);
  // X = 65535, Y = 32768, Rx = 0, Ry = 65535, Z = 1023, Rz = 0, buttons array [1, 4].
  const std::vector<std::uint8_t> r{0xFF, 0xFF, 0x00, 0x80, 0x00, 0x00, 0xFF,
                                    0xFF, 0xFF, 0x03, 0x00, 0x00, 0x01, 0x04};
  ASSERT_TRUE(p.apply(r));
  const auto& s = p.gamepad();
  EXPECT_NEAR(s.left_stick[0], 1.0, 1e-12);
  EXPECT_NEAR(s.right_stick[0], -1.0, 1e-12);
  EXPECT_NEAR(s.right_stick[1], -1.0, 1e-12);
  EXPECT_NEAR(s.left_trigger, 1.0, 1e-12);
  EXPECT_NEAR(s.right_trigger, 0.0, 1e-12);
  EXPECT_TRUE(s.pressed(P::South));
  EXPECT_TRUE(s.pressed(P::North));
  EXPECT_FALSE(s.pressed(P::East));
  // The array lists what is pressed now: an empty list releases everything.
  std::vector<std::uint8_t> r2 = r;
  r2[12] = r2[13] = 0;
  ASSERT_TRUE(p.apply(r2));
  EXPECT_FALSE(p.gamepad().pressed(P::South));
}

struct KindCase {
  std::uint16_t vid, pid, page, usage;
  HidDeviceKind kind;
};

const KindCase kKinds[] = {
    {0x054c, 0x05c4, 0, 0, HidDeviceKind::DualShock4},
    {0x054c, 0x09cc, 0, 0, HidDeviceKind::DualShock4},
    {0x054c, 0x0ce6, 0, 0, HidDeviceKind::DualSense},
    {0x046d, 0xc626, 0, 0, HidDeviceKind::SpaceMouse},
    {0x256f, 0xc635, 0, 0, HidDeviceKind::SpaceMouse},
    {0x0079, 0x0006, 1, 4, HidDeviceKind::GenericGamepad},
    {0x045e, 0x028e, 1, 5, HidDeviceKind::GenericGamepad},
    {0x046d, 0xc52b, 1, 2, HidDeviceKind::Unknown},
    {0x1234, 0x5678, 1, 6, HidDeviceKind::Unknown},
};

TEST(DeviceKinds, ClassifiedByIdThenByUsage) {
  for (const KindCase& c : kKinds) {
    EXPECT_EQ(classify_device(c.vid, c.pid, c.page, c.usage), c.kind)
        << std::hex << c.vid << ":" << c.pid;
  }
}

TEST(DeviceKinds, DeviceIdParsing) {
  EXPECT_EQ(parse_device_id("054c:05c4"),
            std::make_pair(std::uint16_t{0x054c}, std::uint16_t{0x05c4}));
  EXPECT_EQ(parse_device_id("054C:05C4#2"),
            std::make_pair(std::uint16_t{0x054c}, std::uint16_t{0x05c4}));
  for (const char* bad : {"", "054c05c4", "054c:5c4", "zz4c:05c4", "054c:05c4x"}) {
    EXPECT_FALSE(parse_device_id(bad)) << bad;
  }
}

TEST(HidParsers, AHatWhoseRangeSpansAllOfInt32IsReleasedNotOverflowed) {
  // Found by fuzzing (UBSan): logical_max - logical_min + 1 overflowed int32.
  const std::vector<std::uint8_t> descriptor = {
      0x05, 0x01, 0x09, 0x05, 0xA1, 0x01,  // Generic Desktop, Game Pad, Collection (Application)
      0x09, 0x39,                          //   Usage (Hat switch)
      0x17, 0x00, 0x00, 0x00, 0x80,        //   Logical Minimum (-2^31)
      0x27, 0xFF, 0xFF, 0xFF, 0x7F,        //   Logical Maximum (2^31 - 1)
      0x75, 0x20, 0x95, 0x01, 0x81, 0x02,  //   32 bits x 1, Input (Data, Var, Abs)
      0xC0};
  const GenericGamepadDecoder decoder(parse_report_descriptor(descriptor));
  GamepadState s;
  s.set(PadButton::DpadUp, true);
  const std::vector<std::uint8_t> report = {0x00, 0x00, 0x00, 0x00};  // 0: 2^31 above the minimum
  EXPECT_TRUE(decoder.apply(s, report));
  EXPECT_FALSE(s.pressed(PadButton::DpadUp));
  EXPECT_FALSE(s.pressed(PadButton::DpadDown));
}

}  // namespace
}  // namespace vdfx::xr
