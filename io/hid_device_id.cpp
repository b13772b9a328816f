/// @file
/// @brief Device id formatting shared by the hidapi build and the build without it.
#include <cstdio>

#include "io/hid_device.h"

namespace vdfx::io {

std::string format_device_id(std::uint16_t vendor_id, std::uint16_t product_id) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04x:%04x", vendor_id, product_id);
  return buf;
}

}  // namespace vdfx::io
