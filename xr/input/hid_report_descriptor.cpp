/// @file
/// @brief Short-item walker for HID report descriptors (HID 1.11, section 6.2.2).
#include "xr/input/hid_report_descriptor.h"

#include <map>
#include <string>

namespace vdfx::xr {

namespace {

struct Globals {
  std::uint16_t usage_page = 0;
  std::int32_t logical_min = 0;
  std::int32_t logical_max = 0;
  bool logical_max_unsigned = false;  //!< raw bytes of logical max, for the unsigned reading
  std::uint32_t logical_max_raw = 0;
  std::uint32_t report_size = 0;
  std::uint32_t report_count = 0;
  std::uint8_t report_id = 0;
};

struct Locals {
  std::vector<std::uint32_t> usages;  //!< extended: page << 16 | id (page 0 = current page)
  bool have_min = false, have_max = false;
  std::uint32_t usage_min = 0, usage_max = 0;
};

std::int32_t sign_extend(std::uint32_t raw, int size_bytes) {
  if (size_bytes == 1) return static_cast<std::int8_t>(raw);
  if (size_bytes == 2) return static_cast<std::int16_t>(raw);
  return static_cast<std::int32_t>(raw);
}

[[noreturn]] void fail(std::size_t offset, const std::string& what) {
  throw HidDescriptorError("report descriptor byte " + std::to_string(offset) + ": " + what);
}

}  // namespace

HidReportDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes) {
  HidReportDescriptor out;
  Globals g;
  std::vector<Globals> stack;
  Locals l;
  std::map<std::uint8_t, std::uint32_t> bit_pos;  // per report ID
  int depth = 0;
  std::size_t i = 0;
  while (i < bytes.size()) {
    const std::size_t at = i;
    const std::uint8_t prefix = bytes[i++];
    if (prefix == 0xFE) {  // long item: size byte, tag byte, data
      if (i >= bytes.size()) fail(at, "truncated long item");
      i += 2 + bytes[i];
      continue;
    }
    const int size = (prefix & 3) == 3 ? 4 : (prefix & 3);
    const int type = (prefix >> 2) & 3;
    const int tag = prefix >> 4;
    if (i + static_cast<std::size_t>(size) > bytes.size()) fail(at, "item data runs past the end");
    std::uint32_t raw = 0;
    for (int b = 0; b < size; ++b) raw |= static_cast<std::uint32_t>(bytes[i + b]) << (8 * b);
    i += static_cast<std::size_t>(size);
    const std::int32_t sval = size == 0 ? 0 : sign_extend(raw, size);

    if (type == 1) {  // global
      switch (tag) {
        case 0x0: g.usage_page = static_cast<std::uint16_t>(raw); break;
        case 0x1: g.logical_min = sval; break;
        case 0x2:
          g.logical_max = sval;
          g.logical_max_raw = raw;
          g.logical_max_unsigned = true;
          break;
        case 0x7: g.report_size = raw; break;
        case 0x8:
          if (raw == 0 || raw > 255) fail(at, "report ID must be 1..255");
          g.report_id = static_cast<std::uint8_t>(raw);
          out.uses_report_ids = true;
          break;
        case 0x9: g.report_count = raw; break;
        case 0xA: stack.push_back(g); break;
        case 0xB:
          if (stack.empty()) fail(at, "Pop without Push");
          g = stack.back();
          stack.pop_back();
          break;
        default: break;  // physical range, units: not needed for normalised values
      }
      continue;
    }
    if (type == 2) {  // local
      const std::uint32_t usage = size == 4 ? raw : (raw & 0xFFFF);
      switch (tag) {
        case 0x0: l.usages.push_back(usage); break;
        case 0x1:
          l.usage_min = usage;
          l.have_min = true;
          break;
        case 0x2:
          l.usage_max = usage;
          l.have_max = true;
          break;
        default: break;
      }
      continue;
    }
    if (type != 0) fail(at, "reserved item type");
    // main items
    if (tag == 0xA) {  // Collection
      if (depth == 0 && out.application_usage_page == 0 && raw == 1 && !l.usages.empty()) {
        const std::uint32_t u = l.usages.front();
        out.application_usage_page = static_cast<std::uint16_t>(u >> 16 ? u >> 16 : g.usage_page);
        out.application_usage = static_cast<std::uint16_t>(u & 0xFFFF);
      }
      ++depth;
    } else if (tag == 0xC) {  // End Collection
      if (depth == 0) fail(at, "End Collection without Collection");
      --depth;
    } else if (tag == 0x8 || tag == 0x9 || tag == 0xB) {  // Input, Output, Feature
      if (tag == 0x8) {
        if (g.report_size == 0 || g.report_size > 32)
          fail(at, "Input needs a Report Size of 1..32");
        std::int32_t lmax = g.logical_max;
        // Many devices write Logical Maximum 255 in one byte (0xFF) with a minimum of 0: read it
        // unsigned when the minimum is not negative, as the spec's examples intend.
        if (g.logical_min >= 0 && lmax < g.logical_min && g.logical_max_unsigned) {
          lmax = static_cast<std::int32_t>(g.logical_max_raw);
        }
        const bool constant = raw & 1;
        const bool variable = raw & 2;
        const bool relative = raw & 4;
        std::uint32_t& pos = bit_pos[g.report_id];
        // A Report Count read from four bytes can be 2^32 - 1: the fields of one report must fit
        // in the largest report a device can send, and the descriptor in a bounded field list
        // (found by fuzzing: a 100-byte descriptor allocated gigabytes, and the bit counter of a
        // constant item could wrap).
        const std::uint64_t bits = std::uint64_t{g.report_size} * g.report_count;
        if (pos + bits > std::uint64_t{kMaxHidReportBytes} * 8)
          fail(at,
               "the report would be longer than " + std::to_string(kMaxHidReportBytes) + " bytes");
        if (!constant && out.inputs.size() + g.report_count > kMaxHidInputFields)
          fail(at, "more than " + std::to_string(kMaxHidInputFields) + " input fields");
        auto page_of = [&](std::uint32_t u) {
          return static_cast<std::uint16_t>(u >> 16 ? u >> 16 : g.usage_page);
        };
        if (constant) {
          pos += g.report_size * g.report_count;
        } else if (!variable) {  // array: each slot holds a usage index
          HidField f;
          f.report_id = g.report_id;
          f.bit_size = g.report_size;
          f.logical_min = g.logical_min;
          f.logical_max = lmax;
          f.is_array = true;
          const std::uint32_t first =
              l.have_min ? l.usage_min : (l.usages.empty() ? 0 : l.usages.front());
          const std::uint32_t last = l.have_max ? l.usage_max : first;
          f.usage_page = page_of(first);
          f.usage = static_cast<std::uint16_t>(first & 0xFFFF);
          f.usage_max = static_cast<std::uint16_t>(last & 0xFFFF);
          for (std::uint32_t c = 0; c < g.report_count; ++c) {
            f.bit_offset = pos;
            out.inputs.push_back(f);
            pos += g.report_size;
          }
        } else {
          for (std::uint32_t c = 0; c < g.report_count; ++c) {
            std::uint32_t usage = 0;
            if (!l.usages.empty()) {
              usage = l.usages[std::min<std::size_t>(c, l.usages.size() - 1)];
            } else if (l.have_min) {
              usage = std::min(l.usage_min + c, l.have_max ? l.usage_max : l.usage_min + c);
            }
            HidField f;
            f.report_id = g.report_id;
            f.bit_offset = pos;
            f.bit_size = g.report_size;
            f.usage_page = page_of(usage);
            f.usage = static_cast<std::uint16_t>(usage & 0xFFFF);
            f.usage_max = f.usage;
            f.logical_min = g.logical_min;
            f.logical_max = lmax;
            f.is_relative = relative;
            out.inputs.push_back(f);
            pos += g.report_size;
          }
        }
      }
    } else {
      fail(at, "unknown main item tag " + std::to_string(tag));
    }
    l = Locals{};  // local items apply to the next main item only
  }
  if (depth != 0) fail(bytes.size(), "collection not closed");
  return out;
}

bool read_field(const HidField& field, bool uses_report_ids, std::span<const std::uint8_t> report,
                std::int32_t& value) {
  std::size_t start = 0;
  if (uses_report_ids) {
    if (report.empty() || report[0] != field.report_id) return false;
    start = 1;
  }
  const std::size_t last_bit = field.bit_offset + field.bit_size;
  if (start + (last_bit + 7) / 8 > report.size()) return false;
  std::uint64_t raw = 0;
  for (std::uint32_t b = 0; b < field.bit_size; ++b) {
    const std::size_t bit = field.bit_offset + b;
    if ((report[start + bit / 8] >> (bit % 8)) & 1) raw |= std::uint64_t{1} << b;
  }
  if (field.logical_min < 0 && field.bit_size < 32 && (raw >> (field.bit_size - 1)) & 1) {
    raw |= ~((std::uint64_t{1} << field.bit_size) - 1);  // sign-extend
  }
  value = static_cast<std::int32_t>(static_cast<std::uint32_t>(raw & 0xFFFFFFFFu));
  return true;
}

}  // namespace vdfx::xr
