/// @file
/// @brief Which swapchain format vdfx asks an OpenXR runtime for, and how it fills it.
///
/// vdfx's compositor writes display-encoded values: the effects act on the video's encoded
/// values (the contract), so its float eye buffers hold sRGB-encoded colour, not linear light.
/// OpenXR reads an sRGB swapchain format as encoded (it decodes when it samples) and every other
/// format as linear (OpenXR 1.0, XrSwapchain). So the first choice is GL_SRGB8_ALPHA8, filled
/// with the encoded values as they are (GL_FRAMEBUFFER_SRGB off: no second encoding), which is
/// exact. Without an sRGB format, a linear one is filled with the decoded values (the sRGB
/// transfer function applied in the copy): a float or 10-bit format first, RGBA8 last (8-bit
/// linear values band in the dark). docs/openxr.md says the same.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace vdfx::xr {

/// The GL internal formats vdfx can fill (values from the GL headers; this file needs no GL).
inline constexpr std::int64_t kGlSrgb8Alpha8 = 0x8C43;
inline constexpr std::int64_t kGlRgba16f = 0x881A;
inline constexpr std::int64_t kGlRgb10A2 = 0x8059;
inline constexpr std::int64_t kGlRgba8 = 0x8058;

struct SwapchainFormat {
  std::int64_t format = 0;  //!< the GL internal format
  /// True: the runtime decodes sRGB, so the encoded values are copied as they are; false: the
  /// copy decodes them to linear light.
  bool srgb = false;
};

/// vdfx's preference, best first: GL_SRGB8_ALPHA8, GL_RGBA16F, GL_RGB10_A2, GL_RGBA8.
std::span<const std::int64_t> preferred_swapchain_formats();

/// The first of vdfx's preferences that the runtime lists (xrEnumerateSwapchainFormats, in any
/// order); nullopt when it lists none of them.
std::optional<SwapchainFormat> choose_swapchain_format(std::span<const std::int64_t> offered);

/// "GL_SRGB8_ALPHA8" for the formats runtimes commonly list, else the hexadecimal value.
std::string gl_format_name(std::int64_t format);

/// The sRGB transfer functions (IEC 61966-2-1), for the linear fallback and its tests.
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);

}  // namespace vdfx::xr
