/// @file
/// @brief Device states -> actions (the default HID mapping of docs/input.md), with rates
/// integrated over the time passed in. Shared by the live hid backend and replay, so a recorded
/// report stream produces the same actions as the live session did.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>

#include "xr/input/actions.h"
#include "xr/input/hid_parsers.h"

namespace vdfx::xr {

enum class LeftStickRole {
  HeadLook,        //!< left stick turns the head; the d-pad is the left thumbstick
  LeftThumbstick,  //!< left stick is the left thumbstick; the head stays put
};

enum class SpaceMouseTarget { Head, RightHand, LeftHand };

struct HidMappingConfig {
  LeftStickRole left_stick = LeftStickRole::HeadLook;
  double look_rate_deg_s = 90.0;  //!< head turn rate at full stick deflection
  double stick_deadzone = 0.12;   //!< radial, rescaled so output starts at 0 past it
  SpaceMouseTarget spacemouse = SpaceMouseTarget::Head;
  double spacemouse_rate_deg_s = 120.0;  //!< rotation rate at full deflection
  double spacemouse_speed_m_s = 0.5;     //!< hand speed at full deflection (hand target only)
  double spacemouse_deadzone = 0.05;     //!< per axis
  glm::dvec3 head_position{0.0, kDefaultEyeHeight, 0.0};
};

/// Feeds reports of any number of devices (by device id) and produces InputState. Call with
/// non-decreasing times; a time before the last one resets integration to that time.
class HidInputMapper {
 public:
  explicit HidInputMapper(HidMappingConfig config = {});

  /// Declares a device's report descriptor (needed before reports of a generic gamepad).
  /// Throws HidDescriptorError when it cannot be parsed.
  void on_descriptor(const std::string& device, std::span<const std::uint8_t> descriptor);
  /// One input report; an empty report means the device was lost (its controls go neutral).
  /// Returns false when the device is unknown or the report not understood.
  bool on_report(std::int64_t t_ns, const std::string& device,
                 std::span<const std::uint8_t> report);
  /// The device is gone: its controls go neutral, integrated poses stay where they are.
  void on_disconnect(std::int64_t t_ns, const std::string& device);

  /// Integrates up to t_ns and returns the actions.
  InputState state(std::int64_t t_ns);

  /// Devices seen so far and whether a parser exists for them (unknown generic: no descriptor).
  bool knows(const std::string& device) const;

 private:
  void advance(std::int64_t t_ns);
  HidReportParser* parser_for(const std::string& device);

  HidMappingConfig config_;
  std::map<std::string, HidReportParser> parsers_;
  std::map<std::string, std::vector<std::uint8_t>> descriptors_;
  GamepadState pad_;            //!< the latest gamepad report of any gamepad
  SpaceMouseState spacemouse_;  //!< the latest SpaceMouse state
  std::optional<std::int64_t> last_t_;
  glm::dquat head_q_{1.0, 0.0, 0.0, 0.0};
  Pose spacemouse_hand_;  //!< the steered hand's aim when the SpaceMouse targets a hand
};

/// Radial deadzone: |v| < dz -> 0, else scaled so the output runs from 0 at dz to 1 at 1.
glm::dvec2 apply_deadzone(glm::dvec2 v, double deadzone);

}  // namespace vdfx::xr
