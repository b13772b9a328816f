/// @file
/// @brief A HID device behind a tiny interface (read / write / get_feature / close), so parsers
/// and backends are tested with mock devices and recorded reports (style: Monado's os_hid.h).
///
/// The hidapi implementation is io/hid_device_hidapi.cpp (built with VDFX_WITH_HIDAPI); without it
/// io/hid_device_none.cpp provides an empty system.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vdfx::io {

struct HidDeviceInfo {
  std::string path;  //!< OS path, e.g. /dev/hidraw3
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string manufacturer;
  std::string product;
  std::string serial;
  std::uint16_t usage_page = 0;  //!< top-level collection, e.g. 0x01 Generic Desktop
  std::uint16_t usage = 0;       //!< e.g. 0x05 game pad, 0x04 joystick, 0x08 multi-axis
  int interface_number = -1;
};

/// "vvvv:pppp" in lower-case hex: the id recordings and `--input hid:` use.
std::string format_device_id(std::uint16_t vendor_id, std::uint16_t product_id);

class HidDevice {
 public:
  virtual ~HidDevice() = default;
  /// Reads one input report (with its report ID byte when the device numbers its reports).
  /// Returns the byte count, 0 when nothing arrived within timeout_ms, -1 when the device failed
  /// (typically unplugged): the caller closes it and reopens later.
  virtual int read(std::span<std::uint8_t> buffer, int timeout_ms) = 0;
  /// Sends an output report (data[0] = report ID or 0). Returns bytes written or -1.
  virtual int write(std::span<const std::uint8_t> data) = 0;
  /// Gets a feature report; buffer[0] holds the report ID on entry. Returns bytes or -1.
  virtual int get_feature(std::span<std::uint8_t> buffer) = 0;
  /// The report descriptor, or empty when the platform cannot tell.
  virtual std::vector<std::uint8_t> report_descriptor() = 0;
  /// Why the last call failed, for status messages.
  virtual std::string last_error() const = 0;
  virtual void close() = 0;
};

/// Enumeration and opening, as functions so tests substitute a mock system.
struct HidSystem {
  std::function<std::vector<HidDeviceInfo>()> enumerate;
  /// Opens by path; returns null when it cannot (gone, no permission).
  std::function<std::unique_ptr<HidDevice>(const std::string& path)> open;
};

/// True when this build has a real HID backend (hidapi).
bool hid_available();
/// The OS's HID devices (hidapi); an empty system when built without hidapi.
HidSystem default_hid_system();

}  // namespace vdfx::io
