/// @file
/// @brief Fuzz target: the HID report parsers behind live input and replay (xr::HidReportParser
/// for the DualShock 4, DualSense, SpaceMouse and a generic gamepad described by its report
/// descriptor). Input layout: byte 0 picks the device; for the generic pad byte 1 is the
/// descriptor's length and the descriptor follows; the rest is reports, each preceded by its
/// length. Properties: sticks in [-1, 1], triggers in [0, 1], SpaceMouse axes finite; a bad
/// descriptor is xr::HidDescriptorError and nothing else.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "fuzz_check.h"
#include "xr/input/hid_parsers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vdfx::xr;
  if (size < 1) return 0;
  const HidDeviceKind kinds[] = {HidDeviceKind::DualShock4, HidDeviceKind::DualSense,
                                 HidDeviceKind::SpaceMouse, HidDeviceKind::GenericGamepad};
  const HidDeviceKind kind = kinds[data[0] % 4];
  std::size_t at = 1;
  std::span<const std::uint8_t> descriptor;
  if (kind == HidDeviceKind::GenericGamepad) {
    if (size < 2) return 0;
    const std::size_t n = std::min<std::size_t>(data[1], size - 2);
    descriptor = std::span<const std::uint8_t>(data + 2, n);
    at = 2 + n;
  }
  std::optional<HidReportParser> parser;
  try {
    parser.emplace(kind, descriptor);
  } catch (const HidDescriptorError&) {
    return 0;
  }
  while (at < size) {
    const std::size_t n = std::min<std::size_t>(data[at], size - at - 1);
    parser->apply(std::span<const std::uint8_t>(data + at + 1, n));
    at += 1 + n;
    const GamepadState& g = parser->gamepad();
    for (const double v : {g.left_stick[0], g.left_stick[1], g.right_stick[0], g.right_stick[1]})
      VDFX_FUZZ_CHECK(v >= -1.0 && v <= 1.0);
    VDFX_FUZZ_CHECK(g.left_trigger >= 0.0 && g.left_trigger <= 1.0);
    VDFX_FUZZ_CHECK(g.right_trigger >= 0.0 && g.right_trigger <= 1.0);
    for (const double v : parser->spacemouse().translation) VDFX_FUZZ_CHECK(std::isfinite(v));
    for (const double v : parser->spacemouse().rotation) VDFX_FUZZ_CHECK(std::isfinite(v));
  }
  return 0;
}
