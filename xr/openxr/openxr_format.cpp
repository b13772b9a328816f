/// @file
/// @brief Swapchain format choice and names.
#include "xr/openxr/openxr_format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace vdfx::xr {
namespace {

constexpr std::array<std::int64_t, 4> kPreferred{kGlSrgb8Alpha8, kGlRgba16f, kGlRgb10A2, kGlRgba8};

struct Named {
  std::int64_t format;
  const char* name;
};

// Formats OpenGL runtimes list (Monado, SteamVR), and the depth formats they list beside them.
constexpr std::array<Named, 14> kNames{{
    {kGlSrgb8Alpha8, "GL_SRGB8_ALPHA8"},
    {0x8C41, "GL_SRGB8"},
    {kGlRgba16f, "GL_RGBA16F"},
    {0x881B, "GL_RGB16F"},
    {0x8814, "GL_RGBA32F"},
    {kGlRgb10A2, "GL_RGB10_A2"},
    {kGlRgba8, "GL_RGBA8"},
    {0x8051, "GL_RGB8"},
    {0x805B, "GL_RGBA16"},
    {0x8C3A, "GL_R11F_G11F_B10F"},
    {0x81A5, "GL_DEPTH_COMPONENT16"},
    {0x81A6, "GL_DEPTH_COMPONENT24"},
    {0x8CAC, "GL_DEPTH_COMPONENT32F"},
    {0x88F0, "GL_DEPTH24_STENCIL8"},
}};

}  // namespace

std::span<const std::int64_t> preferred_swapchain_formats() {
  return kPreferred;
}

std::optional<SwapchainFormat> choose_swapchain_format(std::span<const std::int64_t> offered) {
  for (const std::int64_t f : kPreferred)
    if (std::find(offered.begin(), offered.end(), f) != offered.end())
      return SwapchainFormat{f, f == kGlSrgb8Alpha8};
  return std::nullopt;
}

std::string gl_format_name(std::int64_t format) {
  for (const Named& n : kNames)
    if (n.format == format) return n.name;
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%llX", static_cast<unsigned long long>(format));
  return buf;
}

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double l) {
  return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

}  // namespace vdfx::xr
