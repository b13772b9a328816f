/// @file
/// @brief The swapchain format vdfx takes from what a runtime offers, and the sRGB transfer
/// functions of its linear fallback.
#include "xr/openxr/openxr_format.h"

#include <gtest/gtest.h>

#include <vector>

namespace vdfx::xr {
namespace {

struct FormatCase {
  const char* name;
  std::vector<std::int64_t> offered;
  std::int64_t expected;  //!< 0: none suits
  bool srgb;
};

// Lists as runtimes give them (Monado's GL list starts with the float and 10-bit formats; a
// depth format never suits).
const FormatCase kCases[] = {
    {"monado_like",
     {kGlRgba16f, kGlRgb10A2, kGlRgba8, kGlSrgb8Alpha8, 0x81A6},
     kGlSrgb8Alpha8,
     true},
    {"srgb_last", {kGlRgba8, kGlSrgb8Alpha8}, kGlSrgb8Alpha8, true},
    {"no_srgb_float_first", {kGlRgba8, kGlRgba16f}, kGlRgba16f, false},
    {"ten_bit_over_eight", {kGlRgba8, kGlRgb10A2}, kGlRgb10A2, false},
    {"rgba8_only", {kGlRgba8}, kGlRgba8, false},
    {"depth_and_srgb8_only", {0x81A6, 0x8C41}, 0, false},
    {"nothing", {}, 0, false},
};

TEST(OpenXrFormat, ChoiceTable) {
  for (const FormatCase& c : kCases) {
    const auto f = choose_swapchain_format(c.offered);
    if (c.expected == 0) {
      EXPECT_FALSE(f.has_value()) << c.name;
      continue;
    }
    ASSERT_TRUE(f.has_value()) << c.name;
    EXPECT_EQ(f->format, c.expected) << c.name;
    EXPECT_EQ(f->srgb, c.srgb) << c.name;
  }
}

TEST(OpenXrFormat, NamesTheCommonFormatsAndPrintsOthersInHex) {
  EXPECT_EQ(gl_format_name(kGlSrgb8Alpha8), "GL_SRGB8_ALPHA8");
  EXPECT_EQ(gl_format_name(kGlRgba16f), "GL_RGBA16F");
  EXPECT_EQ(gl_format_name(0x81A6), "GL_DEPTH_COMPONENT24");
  EXPECT_EQ(gl_format_name(0x1234), "0x1234");
}

TEST(OpenXrFormat, SrgbTransferFunctionsInvertEachOtherAndMatchTheStandard) {
  // IEC 61966-2-1: encoded 0.5 is 0.2140 linear; the linear segment below 0.04045.
  EXPECT_NEAR(srgb_to_linear(0.5), 0.21404, 1e-5);
  EXPECT_NEAR(srgb_to_linear(0.04), 0.04 / 12.92, 1e-12);
  EXPECT_DOUBLE_EQ(srgb_to_linear(1.0), 1.0);
  for (int i = 0; i <= 255; ++i) {
    const double c = i / 255.0;
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(c)), c, 1e-12) << i;
  }
}

}  // namespace
}  // namespace vdfx::xr
