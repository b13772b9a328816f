/// @file
/// @brief How a video frame holds its eyes' images and how much of the sphere they cover
/// (contract: the sidecar's `video.layout` and `video.coverage`; docs/stereo.md).
///
/// Mono: the whole frame is one equirect image. Top-bottom: the left eye's image in the upper
/// half, the right eye's in the lower. Left-right: the left eye's in the left half; right-left:
/// the right eye's in the left half. Coverage 360: each eye's image spans azimuth -180..180;
/// coverage 180 (VR180): azimuth -90..90, centred on azimuth 0, and altitude -90..90 either way.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vdfx::effects {

enum class StereoMode { Mono, TopBottom, LeftRight, RightLeft };
enum class EyeIndex { Left, Right };

/// A pixel rectangle of the frame: columns [x, x + width), rows [y, y + height).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const PixelRect&) const = default;
};

struct StereoLayout {
  StereoMode mode = StereoMode::Mono;
  int coverage_deg = 360;  //!< 360 or 180: degrees of azimuth each eye's image spans
  bool operator==(const StereoLayout&) const = default;
  bool stereo() const { return mode != StereoMode::Mono; }
};

/// Width of the fade to black inside a VR180 image's edge, in degrees of azimuth: full image up
/// to |azimuth| = 90 - kCoverageEdgeDeg, black from |azimuth| = 90 on (docs/stereo.md).
inline constexpr double kCoverageEdgeDeg = 2.0;

/// "mono", "top-bottom", "left-right", "right-left" (the sidecar's and --layout's names).
std::string_view stereo_mode_name(StereoMode mode);
std::optional<StereoMode> stereo_mode_from_name(std::string_view name);
std::string_view eye_index_name(EyeIndex eye);

/// Why `layout` cannot split a `width` x `height` frame (a stereo half must have a whole number
/// of pixels: an odd height for top-bottom, an odd width for left-right), or nothing when it
/// can. Coverage must be 360 or 180.
std::optional<std::string> layout_problem(const StereoLayout& layout, int width, int height);

/// The rectangle of `frame_width` x `frame_height` that holds `eye`'s image (mono: the whole
/// frame for either eye). The layout must divide the frame (layout_problem() is empty).
PixelRect eye_rect(const StereoLayout& layout, EyeIndex eye, int frame_width, int frame_height);

/// A one-line hint for an untagged frame opened as mono whose shape suggests stereo (1:1: a
/// top-bottom 360 pair; 4:1: a side-by-side 360 pair), naming --layout; empty otherwise.
std::string stereo_shape_hint(int width, int height);

/// The fraction of the image shown at azimuth `azimuth_deg` (in (-180, 180]): 1 inside the
/// coverage, a linear fade over kCoverageEdgeDeg inside a VR180 edge, 0 outside.
double coverage_weight(const StereoLayout& layout, double azimuth_deg);

}  // namespace vdfx::effects
