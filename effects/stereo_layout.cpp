/// @file
/// @brief StereoLayout's names, frame split and coverage weight (see stereo_layout.h).
#include "effects/stereo_layout.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace vdfx::effects {
namespace {

constexpr std::array<std::pair<StereoMode, std::string_view>, 4> kNames{{
    {StereoMode::Mono, "mono"},
    {StereoMode::TopBottom, "top-bottom"},
    {StereoMode::LeftRight, "left-right"},
    {StereoMode::RightLeft, "right-left"},
}};

}  // namespace

std::string_view stereo_mode_name(StereoMode mode) {
  for (const auto& [m, name] : kNames)
    if (m == mode) return name;
  return "mono";
}

std::optional<StereoMode> stereo_mode_from_name(std::string_view name) {
  for (const auto& [m, n] : kNames)
    if (n == name) return m;
  return std::nullopt;
}

std::string_view eye_index_name(EyeIndex eye) {
  return eye == EyeIndex::Left ? "left" : "right";
}

std::optional<std::string> layout_problem(const StereoLayout& layout, int width, int height) {
  if (layout.coverage_deg != 360 && layout.coverage_deg != 180)
    return "coverage " + std::to_string(layout.coverage_deg) + " is not 360 or 180";
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const std::string name(stereo_mode_name(layout.mode));
  if (layout.mode == StereoMode::TopBottom && (height < 2 || height % 2 != 0))
    return name + " needs an even frame height; the frame is " + size;
  if ((layout.mode == StereoMode::LeftRight || layout.mode == StereoMode::RightLeft) &&
      (width < 2 || width % 2 != 0))
    return name + " needs an even frame width; the frame is " + size;
  return std::nullopt;
}

PixelRect eye_rect(const StereoLayout& layout, EyeIndex eye, int frame_width, int frame_height) {
  const bool left = eye == EyeIndex::Left;
  const int hw = frame_width / 2, hh = frame_height / 2;
  switch (layout.mode) {
    case StereoMode::TopBottom: return {0, left ? 0 : hh, frame_width, hh};
    case StereoMode::LeftRight: return {left ? 0 : hw, 0, hw, frame_height};
    case StereoMode::RightLeft: return {left ? hw : 0, 0, hw, frame_height};
    case StereoMode::Mono: break;
  }
  return {0, 0, frame_width, frame_height};
}

std::string stereo_shape_hint(int width, int height) {
  if (width <= 0 || height <= 0) return {};
  const char* what = nullptr;
  if (width == height)
    what = "1:1, as a top-bottom stereo 360 pair is";
  else if (width == 4 * height)
    what = "4:1, as a side-by-side stereo 360 pair is";
  if (!what) return {};
  return "the frame is " + std::to_string(width) + "x" + std::to_string(height) + " (" + what +
         ") but carries no stereo tag: opened as mono; give --layout top-bottom|left-right|"
         "right-left if it is stereo";
}

double coverage_weight(const StereoLayout& layout, double azimuth_deg) {
  if (layout.coverage_deg >= 360) return 1.0;
  const double half = 0.5 * layout.coverage_deg;
  return std::clamp((half - std::abs(azimuth_deg)) / kCoverageEdgeDeg, 0.0, 1.0);
}

}  // namespace vdfx::effects
