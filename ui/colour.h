/// @file
/// @brief Straight-alpha sRGB colours and the WCAG 2 contrast ratio used to check the theme.
#pragma once

#include <cstdint>

namespace vdfx::ui {

/// A straight (not premultiplied) sRGB colour, components in [0, 1].
struct Rgba {
  float r = 0.f, g = 0.f, b = 0.f, a = 1.f;
  /// From 0xRRGGBB and an alpha in [0, 1].
  static Rgba hex(std::uint32_t rgb, float alpha = 1.f) {
    return {((rgb >> 16) & 0xff) / 255.f, ((rgb >> 8) & 0xff) / 255.f, (rgb & 0xff) / 255.f, alpha};
  }
  Rgba with_alpha(float alpha) const { return {r, g, b, alpha}; }
  bool operator==(const Rgba&) const = default;
};

/// WCAG 2.x relative luminance of an opaque sRGB colour (alpha ignored).
double relative_luminance(const Rgba& c);
/// WCAG 2.x contrast ratio (L1 + 0.05) / (L2 + 0.05) of two opaque colours, >= 1.
double contrast_ratio(const Rgba& a, const Rgba& b);
/// `top` composited over an opaque `bottom` (straight alpha "over", in sRGB values as a display
/// blends them); the result is opaque.
Rgba over(const Rgba& top, const Rgba& bottom);
/// Hue in degrees [0, 360), saturation and value in [0, 1] to an opaque sRGB colour.
Rgba hsv(double hue_deg, double sat, double val);

}  // namespace vdfx::ui
