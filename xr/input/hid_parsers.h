/// @file
/// @brief Pure HID report parsers: bytes -> device state. They never touch a device, so live
/// reports and recorded ones go through the same code.
///
/// Byte layouts (USB, report ID in byte 0), from public documentation of the devices (Linux
/// hid-sony / hid-playstation report structs, psdevwiki "DS4-USB", 3Dconnexion HID reports as
/// documented by the spacenav projects); see docs/input.md.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "xr/input/hid_report_descriptor.h"

namespace vdfx::xr {

/// Gamepad buttons by position (Sony name / Xbox name).
enum class PadButton {
  South,  //!< cross / A
  East,   //!< circle / B
  West,   //!< square / X
  North,  //!< triangle / Y
  L1,
  R1,
  L2,  //!< digital trigger bit
  R2,
  Select,  //!< share, create / back
  Start,   //!< options / start
  L3,      //!< left stick click
  R3,
  Home,  //!< PS / guide
  Touchpad,
  DpadUp,
  DpadDown,
  DpadLeft,
  DpadRight,
  Count
};

struct GamepadState {
  std::array<double, 2> left_stick{0.0, 0.0};  //!< [-1, 1], +x right, +y up (HID Y is down)
  std::array<double, 2> right_stick{0.0, 0.0};
  double left_trigger = 0.0;   //!< [0, 1]
  double right_trigger = 0.0;  //!< [0, 1]
  std::bitset<static_cast<std::size_t>(PadButton::Count)> buttons;

  bool pressed(PadButton b) const { return buttons.test(static_cast<std::size_t>(b)); }
  void set(PadButton b, bool on) { buttons.set(static_cast<std::size_t>(b), on); }
};

/// A 3Dconnexion SpaceMouse in its own axes as reported: x right, y towards the user, z down;
/// rotations about those axes. Values are raw / kSpaceMouseFullScale, clamped to [-1, 1].
struct SpaceMouseState {
  std::array<double, 3> translation{0.0, 0.0, 0.0};
  std::array<double, 3> rotation{0.0, 0.0, 0.0};
  std::uint32_t buttons = 0;  //!< bit n = button n + 1
};

/// Full deflection of a SpaceMouse axis in raw units (the devices report about +-350).
inline constexpr double kSpaceMouseFullScale = 350.0;

enum class HidDeviceKind { Unknown, DualShock4, DualSense, SpaceMouse, GenericGamepad };

std::string_view device_kind_name(HidDeviceKind kind);

/// The kind for known vendor:product pairs (Sony DS4 / DualSense, 3Dconnexion); Unknown
/// otherwise.
HidDeviceKind known_device_kind(std::uint16_t vendor_id, std::uint16_t product_id);

/// What vdfx would use a device as: a known kind, else GenericGamepad for a Generic Desktop
/// joystick (0x04) or game pad (0x05) collection, else Unknown.
HidDeviceKind classify_device(std::uint16_t vendor_id, std::uint16_t product_id,
                              std::uint16_t usage_page, std::uint16_t usage);

/// Parses "vvvv:pppp" (hex, optional "#n" suffix); nullopt when malformed.
std::optional<std::pair<std::uint16_t, std::uint16_t>> parse_device_id(std::string_view id);

/// DualShock 4 USB input report 0x01 (64 bytes): nullopt for other IDs or short reports.
std::optional<GamepadState> parse_ds4_usb_report(std::span<const std::uint8_t> report);

/// DualSense USB input report 0x01 (64 bytes): nullopt for other IDs or short reports.
std::optional<GamepadState> parse_dualsense_usb_report(std::span<const std::uint8_t> report);

/// Applies one SpaceMouse report to the state: ID 1 translation (7 bytes) or translation and
/// rotation (13 bytes, newer devices), ID 2 rotation, ID 3 buttons. False when not understood.
bool apply_spacemouse_report(SpaceMouseState& state, std::span<const std::uint8_t> report);

/// A generic gamepad described by its report descriptor. Roles: X/Y left stick; Rx/Ry right stick
/// with Z/Rz as triggers when present, else Z/Rz right stick; Simulation Brake/Accelerator as
/// triggers; Hat switch the d-pad; Button page n in the order of generic_button_order().
class GenericGamepadDecoder {
 public:
  explicit GenericGamepadDecoder(HidReportDescriptor descriptor);
  /// Updates the fields this report carries; false when it carries none.
  bool apply(GamepadState& state, std::span<const std::uint8_t> report) const;
  const HidReportDescriptor& descriptor() const { return descriptor_; }

 private:
  enum class Role { LeftX, LeftY, RightX, RightY, LeftTrigger, RightTrigger, Hat, Button };
  struct Binding {
    HidField field;
    Role role;
  };
  HidReportDescriptor descriptor_;
  std::vector<Binding> bindings_;
};

/// Button page usage n (1-based) -> pad button, for n = 1..13; buttons beyond are ignored.
const std::vector<PadButton>& generic_button_order();

/// One device's parser and latest state, chosen by kind.
class HidReportParser {
 public:
  /// For GenericGamepad the descriptor is required (throws HidDescriptorError when bad).
  HidReportParser(HidDeviceKind kind, std::span<const std::uint8_t> descriptor = {});
  /// True when the report changed the state.
  bool apply(std::span<const std::uint8_t> report);
  HidDeviceKind kind() const { return kind_; }
  bool is_spacemouse() const { return kind_ == HidDeviceKind::SpaceMouse; }
  const GamepadState& gamepad() const { return gamepad_; }
  const SpaceMouseState& spacemouse() const { return spacemouse_; }
  /// Neutral state (device lost).
  void reset();

 private:
  HidDeviceKind kind_;
  std::optional<GenericGamepadDecoder> generic_;
  GamepadState gamepad_;
  SpaceMouseState spacemouse_;
};

}  // namespace vdfx::xr
