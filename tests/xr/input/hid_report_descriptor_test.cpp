/// @file
/// @brief Report descriptor parsing on real-world-shaped descriptors, written byte by byte.
#include "xr/input/hid_report_descriptor.h"

#include <gtest/gtest.h>

#include <ostream>

#include "hid_test_data.h"

namespace vdfx::xr {
namespace {

const HidField* find(const HidReportDescriptor& d, std::uint16_t page, std::uint16_t usage) {
  for (const auto& f : d.inputs) {
    if (f.usage_page == page && f.usage == usage) return &f;
  }
  return nullptr;
}

struct FieldRow {
  std::uint16_t page, usage;
  std::uint8_t report_id;
  std::uint32_t bit_offset, bit_size;
  std::int32_t lmin, lmax;
};

struct DescriptorCase {
  const char* name;
  std::vector<std::uint8_t> bytes;
  bool uses_ids;
  std::uint16_t app_usage;
  std::size_t input_count;
  std::vector<FieldRow> fields;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const DescriptorCase& c, std::ostream* os) {
  *os << c.name;
}

const DescriptorCase kDescriptors[] = {
    {"generic_4axes_hat_12buttons",
     test_data::kGenericGamepadDescriptor,
     false,
     0x04,
     4 + 1 + 12 + 8,
     {{0x01, 0x30, 0, 0, 8, 0, 255},
      {0x01, 0x31, 0, 8, 8, 0, 255},
      {0x01, 0x32, 0, 16, 8, 0, 255},
      {0x01, 0x35, 0, 24, 8, 0, 255},
      {0x01, 0x39, 0, 32, 4, 0, 7},
      {0x09, 0x01, 0, 36, 1, 0, 1},
      {0x09, 0x0C, 0, 47, 1, 0, 1},
      {0xFF00, 0x01, 0, 48, 1, 0, 1}}},
    {"report_ids_signed_16bit",
     test_data::kReportIdGamepadDescriptor,
     true,
     0x05,
     2 + 16 + 1,
     {{0x01, 0x30, 1, 0, 16, -32768, 32767},
      {0x01, 0x31, 1, 16, 16, -32768, 32767},
      {0x09, 0x01, 2, 0, 1, 0, 1},
      {0x09, 0x10, 2, 15, 1, 0, 1},
      {0x01, 0x39, 2, 16, 8, 1, 8}}},
    {"xbox_style_triggers_button_array",
     test_data::kXboxStyleDescriptor,
     false,
     0x05,
     4 + 2 + 2,
     {{0x01, 0x30, 0, 0, 16, 0, 65535},
      {0x01, 0x34, 0, 48, 16, 0, 65535},
      {0x01, 0x32, 0, 64, 10, 0, 1023},
      {0x01, 0x35, 0, 80, 10, 0, 1023}}},
    // The DualShock 4's own descriptor (USB): its fields must land on the documented bytes 1-9.
    {"ds4_usb_descriptor",
     test_data::kDs4DescriptorStart,
     true,
     0x05,
     4 + 1 + 14 + 1 + 2,
     {{0x01, 0x30, 1, 0, 8, 0, 255},     // byte 1 LX
      {0x01, 0x35, 1, 24, 8, 0, 255},    // byte 4 RY
      {0x01, 0x39, 1, 32, 4, 0, 7},      // byte 5 low nibble hat
      {0x09, 0x01, 1, 36, 1, 0, 1},      // byte 5 bit 4 square
      {0xFF00, 0x20, 1, 50, 6, 0, 127},  // byte 7 bits 2-7 counter
      {0x01, 0x33, 1, 56, 8, 0, 255},    // byte 8 L2
      {0x01, 0x34, 1, 64, 8, 0, 255}}},  // byte 9 R2
};

class Descriptors : public ::testing::TestWithParam<DescriptorCase> {};

TEST_P(Descriptors, FieldsLandOnTheirBits) {
  const DescriptorCase& c = GetParam();
  const HidReportDescriptor d = parse_report_descriptor(c.bytes);
  EXPECT_EQ(d.uses_report_ids, c.uses_ids);
  EXPECT_EQ(d.application_usage_page, 0x01);
  EXPECT_EQ(d.application_usage, c.app_usage);
  EXPECT_EQ(d.inputs.size(), c.input_count);
  for (const FieldRow& r : c.fields) {
    const HidField* f = find(d, r.page, r.usage);
    ASSERT_NE(f, nullptr) << std::hex << r.page << ":" << r.usage;
    EXPECT_EQ(f->report_id, r.report_id) << r.usage;
    EXPECT_EQ(f->bit_offset, r.bit_offset) << r.usage;
    EXPECT_EQ(f->bit_size, r.bit_size) << r.usage;
    EXPECT_EQ(f->logical_min, r.lmin) << r.usage;
    EXPECT_EQ(f->logical_max, r.lmax) << r.usage;
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, Descriptors, ::testing::ValuesIn(kDescriptors),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(HidDescriptor, ButtonArrayIsOneFieldPerSlot) {
  const HidReportDescriptor d = parse_report_descriptor(test_data::kXboxStyleDescriptor);
  int slots = 0;
  for (const auto& f : d.inputs) {
    if (f.usage_page == 0x09) {
      EXPECT_TRUE(f.is_array);
      EXPECT_EQ(f.usage, 1);
      EXPECT_EQ(f.usage_max, 10);
      EXPECT_EQ(f.bit_offset, 96u + 8u * slots);
      ++slots;
    }
  }
  EXPECT_EQ(slots, 2);
}

TEST(HidDescriptor, ReadFieldSignExtendsAndChecksTheReportId) {
  const HidReportDescriptor d = parse_report_descriptor(test_data::kReportIdGamepadDescriptor);
  const HidField* x = find(d, 0x01, 0x30);
  const HidField* y = find(d, 0x01, 0x31);
  const std::vector<std::uint8_t> r1{0x01, 0x00, 0x80, 0xFF, 0x7F};
  std::int32_t v = 0;
  ASSERT_TRUE(read_field(*x, true, r1, v));
  EXPECT_EQ(v, -32768);
  ASSERT_TRUE(read_field(*y, true, r1, v));
  EXPECT_EQ(v, 32767);
  const std::vector<std::uint8_t> r2{0x02, 0x00, 0x00, 0x00};
  EXPECT_FALSE(read_field(*x, true, r2, v));                                     // other report
  EXPECT_FALSE(read_field(*x, true, std::vector<std::uint8_t>{0x01, 0x00}, v));  // too short
}

struct BadDescriptor {
  const char* name;
  std::vector<std::uint8_t> bytes;
  const char* what;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const BadDescriptor& c, std::ostream* os) {
  *os << c.name;
}

const BadDescriptor kBadDescriptors[] = {
    {"truncated_item", {0x05, 0x01, 0x26, 0xFF}, "byte 2: item data runs past the end"},
    {"unclosed_collection", {0x05, 0x01, 0x09, 0x05, 0xA1, 0x01}, "collection not closed"},
    {"end_without_collection", {0xC0}, "byte 0: End Collection without Collection"},
    {"input_without_size", {0x95, 0x01, 0x81, 0x02}, "byte 2: Input needs a Report Size"},
    {"report_id_zero", {0x85, 0x00}, "report ID must be 1..255"},
    {"pop_without_push", {0xB4}, "Pop without Push"},
    // Issue 11, found by fuzzing: a four-byte Report Count allocated a field per count.
    {"report_count_2_to_the_32",
     {0x75, 0x08, 0x97, 0xFF, 0xFF, 0xFF, 0xFF, 0x81, 0x02},
     "byte 7: the report would be longer than 16384 bytes"},
    // A constant (padding) item's bit counter could wrap around.
    {"padding_2_to_the_32_bits",
     {0x75, 0x20, 0x97, 0x00, 0x00, 0x00, 0x08, 0x81, 0x01},
     "byte 7: the report would be longer than 16384 bytes"},
    // Many fields within the report length: 8 x 1024 one-bit fields.
    {"too_many_fields",
     {0x75, 0x01, 0x96, 0x00, 0x04, 0x81, 0x02, 0x81, 0x02, 0x81, 0x02, 0x81, 0x02, 0x81, 0x02},
     "byte 13: more than 4096 input fields"},
};

class BadDescriptors : public ::testing::TestWithParam<BadDescriptor> {};

TEST_P(BadDescriptors, SayWhere) {
  try {
    parse_report_descriptor(GetParam().bytes);
    FAIL() << "accepted";
  } catch (const HidDescriptorError& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().what), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, BadDescriptors, ::testing::ValuesIn(kBadDescriptors),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vdfx::xr
