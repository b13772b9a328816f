/// @file
/// @brief Hand-written HID descriptors and report builders shared by the HID tests and the
/// recording generator. Layouts follow docs/input.md (public documentation of each device).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

namespace vdfx::xr::test_data {

// A typical cheap USB gamepad (DragonRise-like joystick collection): X, Y, Z, Rz 8-bit, a 4-bit
// hat with a null state, 12 buttons, 8 vendor bits. No report IDs; 7-byte reports.
inline const std::vector<std::uint8_t> kGenericGamepadDescriptor = {
    0x05, 0x01,        // Usage Page (Generic Desktop)
    0x09, 0x04,        // Usage (Joystick)
    0xA1, 0x01,        // Collection (Application)
    0xA1, 0x02,        //   Collection (Logical)
    0x75, 0x08,        //     Report Size (8)
    0x95, 0x04,        //     Report Count (4)
    0x15, 0x00,        //     Logical Minimum (0)
    0x26, 0xFF, 0x00,  //     Logical Maximum (255)
    0x35, 0x00,        //     Physical Minimum (0)
    0x46, 0xFF, 0x00,  //     Physical Maximum (255)
    0x09, 0x30,        //     Usage (X)
    0x09, 0x31,        //     Usage (Y)
    0x09, 0x32,        //     Usage (Z)
    0x09, 0x35,        //     Usage (Rz)
    0x81, 0x02,        //     Input (Data, Var, Abs)
    0x75, 0x04,        //     Report Size (4)
    0x95, 0x01,        //     Report Count (1)
    0x25, 0x07,        //     Logical Maximum (7)
    0x46, 0x3B, 0x01,  //     Physical Maximum (315)
    0x65, 0x14,        //     Unit (degrees)
    0x09, 0x39,        //     Usage (Hat switch)
    0x81, 0x42,        //     Input (Data, Var, Abs, Null state)
    0x65, 0x00,        //     Unit (none)
    0x75, 0x01,        //     Report Size (1)
    0x95, 0x0C,        //     Report Count (12)
    0x25, 0x01,        //     Logical Maximum (1)
    0x45, 0x01,        //     Physical Maximum (1)
    0x05, 0x09,        //     Usage Page (Button)
    0x19, 0x01,        //     Usage Minimum (1)
    0x29, 0x0C,        //     Usage Maximum (12)
    0x81, 0x02,        //     Input (Data, Var, Abs)
    0x06, 0x00, 0xFF,  //     Usage Page (Vendor 0xFF00)
    0x75, 0x01,        //     Report Size (1)
    0x95, 0x08,        //     Report Count (8)
    0x09, 0x01,        //     Usage (1)
    0x81, 0x02,        //     Input (Data, Var, Abs)
    0xC0,              //   End Collection
    0xC0,              // End Collection
};

// A pad that numbers its reports: report 1 sticks (16-bit signed), report 2 16 buttons and an
// 8-bit hat 1..8 (0 = released).
inline const std::vector<std::uint8_t> kReportIdGamepadDescriptor = {
    0x05, 0x01, 0x09, 0x05, 0xA1, 0x01,  // Generic Desktop, Game Pad, Collection (Application)
    0x85, 0x01,                          //   Report ID (1)
    0x16, 0x00, 0x80,                    //   Logical Minimum (-32768)
    0x26, 0xFF, 0x7F,                    //   Logical Maximum (32767)
    0x75, 0x10, 0x95, 0x02,              //   Report Size (16), Count (2)
    0x09, 0x30, 0x09, 0x31,              //   Usage (X), Usage (Y)
    0x81, 0x02,                          //   Input (Data, Var, Abs)
    0x85, 0x02,                          //   Report ID (2)
    0x05, 0x09, 0x19, 0x01, 0x29, 0x10,  //   Button 1..16
    0x15, 0x00, 0x25, 0x01,              //   Logical 0..1
    0x75, 0x01, 0x95, 0x10, 0x81, 0x02,  //   16 x 1 bit, Input
    0x05, 0x01, 0x09, 0x39,              //   Generic Desktop, Hat switch
    0x15, 0x01, 0x25, 0x08,              //   Logical 1..8
    0x75, 0x08, 0x95, 0x01, 0x81, 0x42,  //   8 bits, Input (Null state)
    0xC0,
};

// Xbox-style HID: X, Y, Rx, Ry 16-bit unsigned sticks, Z and Rz 10-bit triggers (each padded to
// 16 bits), two array slots listing pressed buttons 1..10.
inline const std::vector<std::uint8_t> kXboxStyleDescriptor = {
    0x05, 0x01, 0x09, 0x05, 0xA1, 0x01,              // Generic Desktop, Game Pad, App
    0xA1, 0x00,                                      //   Collection (Physical)
    0x09, 0x30, 0x09, 0x31, 0x09, 0x33, 0x09, 0x34,  //     X, Y, Rx, Ry
    0x15, 0x00, 0x27, 0xFF, 0xFF, 0x00, 0x00,        //     Logical 0..65535 (4-byte max)
    0x75, 0x10, 0x95, 0x04, 0x81, 0x02,              //     4 x 16 bits, Input
    0xC0,                                            //   End Collection
    0x09, 0x32, 0x15, 0x00, 0x26, 0xFF, 0x03,        //   Z, Logical 0..1023
    0x75, 0x0A, 0x95, 0x01, 0x81, 0x02,              //   10 bits, Input
    0x75, 0x06, 0x95, 0x01, 0x81, 0x03,              //   6 bits constant padding
    0x09, 0x35, 0x75, 0x0A, 0x95, 0x01, 0x81, 0x02,  //   Rz 10 bits
    0x75, 0x06, 0x95, 0x01, 0x81, 0x03,              //   padding
    0x05, 0x09, 0x19, 0x01, 0x29, 0x0A,              //   Button 1..10
    0x15, 0x01, 0x25, 0x0A, 0x75, 0x08, 0x95, 0x02, 0x81, 0x00,  // array: 2 slots of 8 bits
    0xC0,
};

// The start of the DualShock 4's USB descriptor (input report 1), as published for the device.
inline const std::vector<std::uint8_t> kDs4DescriptorStart = {
    0x05, 0x01, 0x09, 0x05, 0xA1, 0x01, 0x85, 0x01,  // Game Pad, Report ID 1
    0x09, 0x30, 0x09, 0x31, 0x09, 0x32, 0x09, 0x35,  // X, Y, Z, Rz
    0x15, 0x00, 0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x04, 0x81, 0x02,
    0x09, 0x39, 0x15, 0x00, 0x25, 0x07, 0x35, 0x00, 0x46, 0x3B, 0x01,
    0x65, 0x14, 0x75, 0x04, 0x95, 0x01, 0x81, 0x42, 0x65, 0x00,  // hat
    0x05, 0x09, 0x19, 0x01, 0x29, 0x0E, 0x15, 0x00, 0x25, 0x01, 0x75,
    0x01, 0x95, 0x0E, 0x81, 0x02,  // 14 buttons
    0x06, 0x00, 0xFF, 0x09, 0x20, 0x75, 0x06, 0x95, 0x01, 0x15, 0x00,
    0x25, 0x7F, 0x81, 0x02,  // 6-bit counter
    0x05, 0x01, 0x09, 0x33, 0x09, 0x34, 0x15, 0x00, 0x26, 0xFF, 0x00,
    0x75, 0x08, 0x95, 0x02, 0x81, 0x02,  // Rx, Ry: the analog L2, R2
    0xC0,
};

using Edits = std::initializer_list<std::pair<int, std::uint8_t>>;

// A DualShock 4 USB report 0x01 at rest (sticks 0x80, hat 8 = released), then edits.
inline std::vector<std::uint8_t> ds4_report(Edits edits = {}) {
  std::vector<std::uint8_t> r(64, 0);
  r[0] = 0x01;
  r[1] = r[2] = r[3] = r[4] = 0x80;
  r[5] = 0x08;
  for (auto [i, v] : edits) r[i] = v;
  return r;
}

// A DualSense USB report 0x01 at rest (sticks 0x80, hat 8 at byte 8), then edits.
inline std::vector<std::uint8_t> dualsense_report(Edits edits = {}) {
  std::vector<std::uint8_t> r(64, 0);
  r[0] = 0x01;
  r[1] = r[2] = r[3] = r[4] = 0x80;
  r[8] = 0x08;
  for (auto [i, v] : edits) r[i] = v;
  return r;
}

// SpaceMouse report with three little-endian int16 values.
inline std::vector<std::uint8_t> spacemouse_report(std::uint8_t id, int a, int b, int c) {
  std::vector<std::uint8_t> r{id};
  for (int v : {a, b, c}) {
    const auto u = static_cast<std::uint16_t>(static_cast<std::int16_t>(v));
    r.push_back(static_cast<std::uint8_t>(u & 0xFF));
    r.push_back(static_cast<std::uint8_t>(u >> 8));
  }
  return r;
}

// A report of kGenericGamepadDescriptor: axes, hat (8 = released), buttons bitmask (bit 0 = 1).
inline std::vector<std::uint8_t> generic_report(std::uint8_t x, std::uint8_t y, std::uint8_t z,
                                                std::uint8_t rz, std::uint8_t hat,
                                                std::uint16_t buttons) {
  return {x,
          y,
          z,
          rz,
          static_cast<std::uint8_t>((hat & 0x0F) | ((buttons & 0x0F) << 4)),
          static_cast<std::uint8_t>(buttons >> 4),
          0x00};
}

}  // namespace vdfx::xr::test_data
