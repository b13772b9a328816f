/// @file
/// @brief The HID system of a build without hidapi: no devices, nothing opens.
#include "io/hid_device.h"

#ifndef VDFX_WITH_HIDAPI

namespace vdfx::io {

bool hid_available() {
  return false;
}

HidSystem default_hid_system() {
  return {[] { return std::vector<HidDeviceInfo>{}; },
          [](const std::string&) { return std::unique_ptr<HidDevice>(); }};
}

}  // namespace vdfx::io

#endif
