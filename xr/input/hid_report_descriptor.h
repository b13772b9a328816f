/// @file
/// @brief HID report descriptor parsing (short items) into input fields with bit positions.
///
/// Follows the USB "Device Class Definition for HID 1.11", section 6.2.2: items are a prefix byte
/// (bits 0-1 size 0/1/2/4 bytes, bits 2-3 type main/global/local, bits 4-7 tag) and little-endian
/// data. Handled: Usage Page, Usage (also 4-byte extended), Usage Minimum/Maximum, Logical
/// Minimum/Maximum, Report Size/Count/ID, Push/Pop, Input, Collection/End Collection. Output and
/// Feature items are skipped (they do not move input bit positions); long items are skipped.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace vdfx::xr {

/// A descriptor that cannot be parsed; the message names the byte offset.
class HidDescriptorError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HidField {
  std::uint8_t report_id = 0;    //!< 0 when the device does not number its reports
  std::uint32_t bit_offset = 0;  //!< from the first data byte (after the report ID byte)
  std::uint32_t bit_size = 0;
  std::uint16_t usage_page = 0;
  std::uint16_t usage = 0;      //!< for array fields: the first usage of the range
  std::uint16_t usage_max = 0;  //!< for array fields: the last usage of the range
  std::int32_t logical_min = 0;
  std::int32_t logical_max = 0;
  bool is_array =
      false;  //!< value selects a usage (usage + value - logical_min); 0/out of range: none
  bool is_relative = false;
};

struct HidReportDescriptor {
  std::vector<HidField> inputs;  //!< constant (padding) fields are left out
  bool uses_report_ids = false;
  std::uint16_t application_usage_page = 0;  //!< of the first application collection
  std::uint16_t application_usage = 0;
};

/// The longest input report a descriptor may describe (Linux's HID_MAX_BUFFER_SIZE) and the most
/// input fields in all (a gamepad has a few dozen).
inline constexpr std::size_t kMaxHidReportBytes = 16384;
inline constexpr std::size_t kMaxHidInputFields = 4096;

/// Throws HidDescriptorError on a truncated item, unbalanced collections, a field without a
/// report size/count, or a report or field list beyond the limits above.
HidReportDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes);

/// The raw value of a field in a report (report[0] is the ID byte when the device uses IDs),
/// sign-extended when logical_min < 0. Returns false when the report is too short or has
/// another report ID.
bool read_field(const HidField& field, bool uses_report_ids, std::span<const std::uint8_t> report,
                std::int32_t& value);

}  // namespace vdfx::xr
