/// @file
/// @brief The swapchain format vdfx takes from what a runtime offers, and the sRGB transfer
/// functions of its linear fallback, and the formats' names.
#include "xr/openxr/openxr_format.h"

#include <epoxy/gl.h>
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

/// Each sized format of GL 4.6 core (tables 8.12 and 8.13) beside its value from the GL headers
/// (macros only: nothing of GL is linked), so a wrong number in the table fails.
struct NamedFormat {
  std::int64_t value;
  const char* name;
};
#define VDFX_GL(name) \
  NamedFormat {       \
    name, #name       \
  }
const NamedFormat kGlSizedFormats[] = {
    VDFX_GL(GL_R8),
    VDFX_GL(GL_R8_SNORM),
    VDFX_GL(GL_R16),
    VDFX_GL(GL_R16_SNORM),
    VDFX_GL(GL_RG8),
    VDFX_GL(GL_RG8_SNORM),
    VDFX_GL(GL_RG16),
    VDFX_GL(GL_RG16_SNORM),
    VDFX_GL(GL_R3_G3_B2),
    VDFX_GL(GL_RGB4),
    VDFX_GL(GL_RGB5),
    VDFX_GL(GL_RGB565),
    VDFX_GL(GL_RGB8),
    VDFX_GL(GL_RGB8_SNORM),
    VDFX_GL(GL_RGB10),
    VDFX_GL(GL_RGB12),
    VDFX_GL(GL_RGB16),
    VDFX_GL(GL_RGB16_SNORM),
    VDFX_GL(GL_RGBA2),
    VDFX_GL(GL_RGBA4),
    VDFX_GL(GL_RGB5_A1),
    VDFX_GL(GL_RGBA8),
    VDFX_GL(GL_RGBA8_SNORM),
    VDFX_GL(GL_RGB10_A2),
    VDFX_GL(GL_RGB10_A2UI),
    VDFX_GL(GL_RGBA12),
    VDFX_GL(GL_RGBA16),
    VDFX_GL(GL_RGBA16_SNORM),
    VDFX_GL(GL_SRGB8),
    VDFX_GL(GL_SRGB8_ALPHA8),
    VDFX_GL(GL_R16F),
    VDFX_GL(GL_RG16F),
    VDFX_GL(GL_RGB16F),
    VDFX_GL(GL_RGBA16F),
    VDFX_GL(GL_R32F),
    VDFX_GL(GL_RG32F),
    VDFX_GL(GL_RGB32F),
    VDFX_GL(GL_RGBA32F),
    VDFX_GL(GL_R11F_G11F_B10F),
    VDFX_GL(GL_RGB9_E5),
    VDFX_GL(GL_R8I),
    VDFX_GL(GL_R8UI),
    VDFX_GL(GL_R16I),
    VDFX_GL(GL_R16UI),
    VDFX_GL(GL_R32I),
    VDFX_GL(GL_R32UI),
    VDFX_GL(GL_RG8I),
    VDFX_GL(GL_RG8UI),
    VDFX_GL(GL_RG16I),
    VDFX_GL(GL_RG16UI),
    VDFX_GL(GL_RG32I),
    VDFX_GL(GL_RG32UI),
    VDFX_GL(GL_RGB8I),
    VDFX_GL(GL_RGB8UI),
    VDFX_GL(GL_RGB16I),
    VDFX_GL(GL_RGB16UI),
    VDFX_GL(GL_RGB32I),
    VDFX_GL(GL_RGB32UI),
    VDFX_GL(GL_RGBA8I),
    VDFX_GL(GL_RGBA8UI),
    VDFX_GL(GL_RGBA16I),
    VDFX_GL(GL_RGBA16UI),
    VDFX_GL(GL_RGBA32I),
    VDFX_GL(GL_RGBA32UI),
    VDFX_GL(GL_DEPTH_COMPONENT16),
    VDFX_GL(GL_DEPTH_COMPONENT24),
    VDFX_GL(GL_DEPTH_COMPONENT32),
    VDFX_GL(GL_DEPTH_COMPONENT32F),
    VDFX_GL(GL_DEPTH24_STENCIL8),
    VDFX_GL(GL_DEPTH32F_STENCIL8),
    VDFX_GL(GL_STENCIL_INDEX8),
};
#undef VDFX_GL

TEST(OpenXrFormat, NamesEverySizedFormatOfGl46AndPrintsOthersInHex) {
  for (const NamedFormat& r : kGlSizedFormats) EXPECT_EQ(gl_format_name(r.value), r.name);
  EXPECT_EQ(gl_format_name(0x8CAD), "GL_DEPTH32F_STENCIL8") << "Monado lists it";
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
