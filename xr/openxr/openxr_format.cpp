/// @file
/// @brief Swapchain format choice and the sRGB transfer functions (names: gl_format_names.cpp).
#include "xr/openxr/openxr_format.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vdfx::xr {
namespace {

constexpr std::array<std::int64_t, 4> kPreferred{kGlSrgb8Alpha8, kGlRgba16f, kGlRgb10A2, kGlRgba8};

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

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double l) {
  return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

}  // namespace vdfx::xr
