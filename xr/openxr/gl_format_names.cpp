/// @file
/// @brief gl_format_name (xr/openxr/openxr_format.h): the name of every sized internal format of
/// OpenGL 4.6 core (its tables 8.12 and 8.13: colour, depth and stencil), the values from the GL
/// headers. A runtime lists swapchain formats as these numbers; `vdfx hmd openxr` prints names.
#include <array>
#include <cstdio>

#include "xr/openxr/openxr_format.h"

namespace vdfx::xr {
namespace {

struct Named {
  std::int64_t format;
  const char* name;
};

constexpr std::array<Named, 71> kNames{{
    {0x8229, "GL_R8"},
    {0x8F94, "GL_R8_SNORM"},
    {0x822A, "GL_R16"},
    {0x8F98, "GL_R16_SNORM"},
    {0x822B, "GL_RG8"},
    {0x8F95, "GL_RG8_SNORM"},
    {0x822C, "GL_RG16"},
    {0x8F99, "GL_RG16_SNORM"},
    {0x2A10, "GL_R3_G3_B2"},
    {0x804F, "GL_RGB4"},
    {0x8050, "GL_RGB5"},
    {0x8D62, "GL_RGB565"},
    {0x8051, "GL_RGB8"},
    {0x8F96, "GL_RGB8_SNORM"},
    {0x8052, "GL_RGB10"},
    {0x8053, "GL_RGB12"},
    {0x8054, "GL_RGB16"},
    {0x8F9A, "GL_RGB16_SNORM"},
    {0x8055, "GL_RGBA2"},
    {0x8056, "GL_RGBA4"},
    {0x8057, "GL_RGB5_A1"},
    {0x8058, "GL_RGBA8"},
    {0x8F97, "GL_RGBA8_SNORM"},
    {0x8059, "GL_RGB10_A2"},
    {0x906F, "GL_RGB10_A2UI"},
    {0x805A, "GL_RGBA12"},
    {0x805B, "GL_RGBA16"},
    {0x8F9B, "GL_RGBA16_SNORM"},
    {0x8C41, "GL_SRGB8"},
    {0x8C43, "GL_SRGB8_ALPHA8"},
    {0x822D, "GL_R16F"},
    {0x822F, "GL_RG16F"},
    {0x881B, "GL_RGB16F"},
    {0x881A, "GL_RGBA16F"},
    {0x822E, "GL_R32F"},
    {0x8230, "GL_RG32F"},
    {0x8815, "GL_RGB32F"},
    {0x8814, "GL_RGBA32F"},
    {0x8C3A, "GL_R11F_G11F_B10F"},
    {0x8C3D, "GL_RGB9_E5"},
    {0x8231, "GL_R8I"},
    {0x8232, "GL_R8UI"},
    {0x8233, "GL_R16I"},
    {0x8234, "GL_R16UI"},
    {0x8235, "GL_R32I"},
    {0x8236, "GL_R32UI"},
    {0x8237, "GL_RG8I"},
    {0x8238, "GL_RG8UI"},
    {0x8239, "GL_RG16I"},
    {0x823A, "GL_RG16UI"},
    {0x823B, "GL_RG32I"},
    {0x823C, "GL_RG32UI"},
    {0x8D8F, "GL_RGB8I"},
    {0x8D7D, "GL_RGB8UI"},
    {0x8D89, "GL_RGB16I"},
    {0x8D77, "GL_RGB16UI"},
    {0x8D83, "GL_RGB32I"},
    {0x8D71, "GL_RGB32UI"},
    {0x8D8E, "GL_RGBA8I"},
    {0x8D7C, "GL_RGBA8UI"},
    {0x8D88, "GL_RGBA16I"},
    {0x8D76, "GL_RGBA16UI"},
    {0x8D82, "GL_RGBA32I"},
    {0x8D70, "GL_RGBA32UI"},
    {0x81A5, "GL_DEPTH_COMPONENT16"},
    {0x81A6, "GL_DEPTH_COMPONENT24"},
    {0x81A7, "GL_DEPTH_COMPONENT32"},
    {0x8CAC, "GL_DEPTH_COMPONENT32F"},
    {0x88F0, "GL_DEPTH24_STENCIL8"},
    {0x8CAD, "GL_DEPTH32F_STENCIL8"},
    {0x8D48, "GL_STENCIL_INDEX8"},
}};

}  // namespace

std::string gl_format_name(std::int64_t format) {
  for (const Named& n : kNames)
    if (n.format == format) return n.name;
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%llX", static_cast<unsigned long long>(format));
  return buf;
}

}  // namespace vdfx::xr
