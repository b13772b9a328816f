/// @file
/// @brief `vdfx devices`: lists the HID devices hidapi sees and what vdfx would use them as.
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/cli/command_functions.h"
#include "io/hid_device.h"
#include "xr/input/hid_parsers.h"

namespace vdfx::app {

int cmd_devices(const Args& args) {
  bool all = false;
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h") {
      std::cout
          << "usage: vdfx devices [--all]\n\n"
             "Lists HID devices (via hidapi) with the id `--input hid:ID` takes and what vdfx\n"
             "uses them as (DualShock 4, DualSense, SpaceMouse, generic gamepad).\n"
             "  --all   also list devices vdfx cannot use (keyboards, mice, ...)\n";
      return kExitOk;
    }
    if (a == "--all") {
      all = true;
    } else {
      std::cerr << "vdfx devices: unknown option '" << a << "' (vdfx devices --help)\n";
      return kExitUsage;
    }
  }
  if (!io::hid_available()) {
    std::cout << "this build has no HID support (configured with VDFX_WITH_HIDAPI=OFF)\n";
    return kExitOk;
  }
  const auto devices = io::default_hid_system().enumerate();
  int shown = 0;
  for (const auto& d : devices) {
    const auto kind = xr::classify_device(d.vendor_id, d.product_id, d.usage_page, d.usage);
    if (kind == xr::HidDeviceKind::Unknown && !all) continue;
    if (shown++ == 0) {
      std::cout << std::left << std::setw(11) << "id" << std::setw(18) << "path" << std::setw(12)
                << "usage" << std::setw(18) << "vdfx uses it as"
                << "name\n";
    }
    std::ostringstream usage;
    usage << std::hex << std::setfill('0') << std::setw(2) << d.usage_page << ":" << std::setw(2)
          << d.usage;
    std::cout << std::left << std::setw(11) << io::format_device_id(d.vendor_id, d.product_id)
              << std::setw(18) << d.path << std::setw(12) << usage.str() << std::setw(18)
              << xr::device_kind_name(kind) << d.manufacturer << (d.manufacturer.empty() ? "" : " ")
              << d.product << "\n";
  }
  if (shown == 0) {
    std::cout << (all ? "no HID devices found"
                      : "no supported HID devices found (--all lists every HID device)")
              << " (on Linux, reading /dev/hidraw* may need a udev rule)\n";
  }
  return kExitOk;
}

}  // namespace vdfx::app
