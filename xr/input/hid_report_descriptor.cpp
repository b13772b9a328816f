/// @file
/// @brief Short-item walker for HID report descriptors (HID 1.11, section 6.2.2).
#include "xr/input/hid_report_descriptor.h"

#include <map>
#include <string>
#include <utility>

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

/// One short item: where it starts, its prefix's fields and its data (little-endian).
struct Item {
  std::size_t at = 0;
  int size = 0;  //!< data bytes: 0, 1, 2 or 4
  int type = 0;  //!< 0 main, 1 global, 2 local, 3 reserved
  int tag = 0;
  std::uint32_t raw = 0;
  std::int32_t sval = 0;  //!< raw sign-extended from its size
};

/// Reads the item at `i` and moves `i` past it; false for a long item (skipped, not returned).
bool next_item(std::span<const std::uint8_t> bytes, std::size_t& i, Item& item) {
  item.at = i;
  const std::uint8_t prefix = bytes[i++];
  if (prefix == 0xFE) {  // long item: size byte, tag byte, data
    if (i >= bytes.size()) fail(item.at, "truncated long item");
    i += 2 + bytes[i];
    return false;
  }
  item.size = (prefix & 3) == 3 ? 4 : (prefix & 3);
  item.type = (prefix >> 2) & 3;
  item.tag = prefix >> 4;
  if (i + static_cast<std::size_t>(item.size) > bytes.size())
    fail(item.at, "item data runs past the end");
  item.raw = 0;
  for (int b = 0; b < item.size; ++b)
    item.raw |= static_cast<std::uint32_t>(bytes[i + b]) << (8 * b);
  i += static_cast<std::size_t>(item.size);
  item.sval = item.size == 0 ? 0 : sign_extend(item.raw, item.size);
  return true;
}

/// The parser's state between items: the global and local item state of HID 1.11 (6.2.2.7-8),
/// the collections open and each report's next bit.
class Walker {
 public:
  void global(const Item& it);
  void local(const Item& it);
  void main(const Item& it);
  HidReportDescriptor finish(std::size_t end) {
    if (depth_ != 0) fail(end, "collection not closed");
    return std::move(out_);
  }

 private:
  void input(const Item& it);
  void array_fields(std::uint32_t count, std::int32_t lmax, std::uint32_t& pos);
  void variable_fields(std::uint32_t count, std::int32_t lmax, bool relative, std::uint32_t& pos);
  std::uint16_t page_of(std::uint32_t usage) const {
    return static_cast<std::uint16_t>(usage >> 16 ? usage >> 16 : g_.usage_page);
  }

  HidReportDescriptor out_;
  Globals g_;
  std::vector<Globals> stack_;
  Locals l_;
  std::map<std::uint8_t, std::uint32_t> bit_pos_;  // per report ID
  int depth_ = 0;
};

void Walker::global(const Item& it) {
  switch (it.tag) {
    case 0x0: g_.usage_page = static_cast<std::uint16_t>(it.raw); break;
    case 0x1: g_.logical_min = it.sval; break;
    case 0x2:
      g_.logical_max = it.sval;
      g_.logical_max_raw = it.raw;
      g_.logical_max_unsigned = true;
      break;
    case 0x7: g_.report_size = it.raw; break;
    case 0x8:
      if (it.raw == 0 || it.raw > 255) fail(it.at, "report ID must be 1..255");
      g_.report_id = static_cast<std::uint8_t>(it.raw);
      out_.uses_report_ids = true;
      break;
    case 0x9: g_.report_count = it.raw; break;
    case 0xA: stack_.push_back(g_); break;
    case 0xB:
      if (stack_.empty()) fail(it.at, "Pop without Push");
      g_ = stack_.back();
      stack_.pop_back();
      break;
    default: break;  // physical range, units: not needed for normalised values
  }
}

void Walker::local(const Item& it) {
  const std::uint32_t usage = it.size == 4 ? it.raw : (it.raw & 0xFFFF);
  switch (it.tag) {
    case 0x0: l_.usages.push_back(usage); break;
    case 0x1:
      l_.usage_min = usage;
      l_.have_min = true;
      break;
    case 0x2:
      l_.usage_max = usage;
      l_.have_max = true;
      break;
    default: break;
  }
}

void Walker::main(const Item& it) {
  if (it.tag == 0xA) {  // Collection
    if (depth_ == 0 && out_.application_usage_page == 0 && it.raw == 1 && !l_.usages.empty()) {
      const std::uint32_t u = l_.usages.front();
      out_.application_usage_page = page_of(u);
      out_.application_usage = static_cast<std::uint16_t>(u & 0xFFFF);
    }
    ++depth_;
  } else if (it.tag == 0xC) {  // End Collection
    if (depth_ == 0) fail(it.at, "End Collection without Collection");
    --depth_;
  } else if (it.tag == 0x8) {  // Input
    input(it);
  } else if (it.tag != 0x9 && it.tag != 0xB) {  // not Output or Feature (no input bits)
    fail(it.at, "unknown main item tag " + std::to_string(it.tag));
  }
  l_ = Locals{};  // local items apply to the next main item only
}

void Walker::input(const Item& it) {
  if (g_.report_size == 0 || g_.report_size > 32) fail(it.at, "Input needs a Report Size of 1..32");
  std::int32_t lmax = g_.logical_max;
  // Many devices write Logical Maximum 255 in one byte (0xFF) with a minimum of 0: read it
  // unsigned when the minimum is not negative, as the spec's examples intend.
  if (g_.logical_min >= 0 && lmax < g_.logical_min && g_.logical_max_unsigned) {
    lmax = static_cast<std::int32_t>(g_.logical_max_raw);
  }
  const bool constant = it.raw & 1;
  const bool variable = it.raw & 2;
  const bool relative = it.raw & 4;
  std::uint32_t& pos = bit_pos_[g_.report_id];
  // A Report Count read from four bytes can be 2^32 - 1: the fields of one report must fit
  // in the largest report a device can send, and the descriptor in a bounded field list
  // (found by fuzzing: a 100-byte descriptor allocated gigabytes, and the bit counter of a
  // constant item could wrap).
  const std::uint64_t bits = std::uint64_t{g_.report_size} * g_.report_count;
  if (pos + bits > std::uint64_t{kMaxHidReportBytes} * 8)
    fail(it.at, "the report would be longer than " + std::to_string(kMaxHidReportBytes) + " bytes");
  if (!constant && out_.inputs.size() + g_.report_count > kMaxHidInputFields)
    fail(it.at, "more than " + std::to_string(kMaxHidInputFields) + " input fields");
  if (constant)
    pos += g_.report_size * g_.report_count;
  else if (!variable)  // array: each slot holds a usage index
    array_fields(g_.report_count, lmax, pos);
  else
    variable_fields(g_.report_count, lmax, relative, pos);
}

void Walker::array_fields(std::uint32_t count, std::int32_t lmax, std::uint32_t& pos) {
  HidField f;
  f.report_id = g_.report_id;
  f.bit_size = g_.report_size;
  f.logical_min = g_.logical_min;
  f.logical_max = lmax;
  f.is_array = true;
  const std::uint32_t first =
      l_.have_min ? l_.usage_min : (l_.usages.empty() ? 0 : l_.usages.front());
  const std::uint32_t last = l_.have_max ? l_.usage_max : first;
  f.usage_page = page_of(first);
  f.usage = static_cast<std::uint16_t>(first & 0xFFFF);
  f.usage_max = static_cast<std::uint16_t>(last & 0xFFFF);
  for (std::uint32_t c = 0; c < count; ++c) {
    f.bit_offset = pos;
    out_.inputs.push_back(f);
    pos += g_.report_size;
  }
}

void Walker::variable_fields(std::uint32_t count, std::int32_t lmax, bool relative,
                             std::uint32_t& pos) {
  for (std::uint32_t c = 0; c < count; ++c) {
    std::uint32_t usage = 0;
    if (!l_.usages.empty()) {
      usage = l_.usages[std::min<std::size_t>(c, l_.usages.size() - 1)];
    } else if (l_.have_min) {
      usage = std::min(l_.usage_min + c, l_.have_max ? l_.usage_max : l_.usage_min + c);
    }
    HidField f;
    f.report_id = g_.report_id;
    f.bit_offset = pos;
    f.bit_size = g_.report_size;
    f.usage_page = page_of(usage);
    f.usage = static_cast<std::uint16_t>(usage & 0xFFFF);
    f.usage_max = f.usage;
    f.logical_min = g_.logical_min;
    f.logical_max = lmax;
    f.is_relative = relative;
    out_.inputs.push_back(f);
    pos += g_.report_size;
  }
}

}  // namespace

HidReportDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes) {
  Walker w;
  std::size_t i = 0;
  while (i < bytes.size()) {
    Item it;
    if (!next_item(bytes, i, it)) continue;
    if (it.type == 1)
      w.global(it);
    else if (it.type == 2)
      w.local(it);
    else if (it.type == 0)
      w.main(it);
    else
      fail(it.at, "reserved item type");
  }
  return w.finish(bytes.size());
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
