/// @file
/// @brief Fuzz target: the HID report descriptor parser (xr::parse_report_descriptor) and the
/// field reader on a report made of the same bytes. Properties: a bad descriptor is
/// xr::HidDescriptorError and nothing else; fields stay within what their sizes can address.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_check.h"
#include "xr/input/hid_report_descriptor.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vdfx::xr;
  const std::span<const std::uint8_t> bytes(data, size);
  HidReportDescriptor d;
  try {
    d = parse_report_descriptor(bytes);
  } catch (const HidDescriptorError&) {
    return 0;
  }
  for (const HidField& f : d.inputs) {
    VDFX_FUZZ_CHECK(f.bit_size > 0 && f.bit_size <= 32);
    std::int32_t v = 0;
    (void)read_field(f, d.uses_report_ids, bytes, v);  // any report: must not read out of bounds
  }
  return 0;
}
