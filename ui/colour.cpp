/// @file
/// @brief Contrast and colour conversions of colour.h (WCAG 2.1, "relative luminance").
#include "ui/colour.h"

#include <algorithm>
#include <cmath>

namespace vdfx::ui {

namespace {
double linear(double c) {  // sRGB transfer inverse, as WCAG 2.1 defines it
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
}  // namespace

double relative_luminance(const Rgba& c) {
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

double contrast_ratio(const Rgba& a, const Rgba& b) {
  const double la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

Rgba over(const Rgba& top, const Rgba& bottom) {
  const float a = top.a;
  return {top.r * a + bottom.r * (1 - a), top.g * a + bottom.g * (1 - a),
          top.b * a + bottom.b * (1 - a), 1.f};
}

Rgba hsv(double hue_deg, double sat, double val) {
  const double h = std::fmod(std::fmod(hue_deg, 360.0) + 360.0, 360.0) / 60.0;
  const double c = val * sat;
  const double x = c * (1 - std::abs(std::fmod(h, 2.0) - 1));
  const double m = val - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  return {static_cast<float>(r + m), static_cast<float>(g + m), static_cast<float>(b + m), 1.f};
}

}  // namespace vdfx::ui
