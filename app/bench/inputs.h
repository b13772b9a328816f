/// @file
/// @brief Inputs shared by `vdfx bench` and the Google Benchmark targets (tests/bench/): seeded
/// random keyframes, the synthetic 4K equirect frame, the real CC0 panorama, the generic90 eye's
/// lens and a grid of points over its panel. Deterministic, so figures of two runs compare.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/effect_types.h"
#include "effects/keyframe.h"
#include "effects/lens_model.h"
#include "xr/headset/session.h"

namespace vdfx::app::bench {

/// `n` keyframes of `dim` parameters in [0, 4], directions uniform on the sphere, frames uniform
/// in [0, max_frame], from a seeded generator.
std::vector<effects::Keyframe> random_keyframes(int n, int dim, std::uint64_t seed,
                                                std::int64_t max_frame = 3000);

/// A 3840 x 1920 CV_8UC3 BGR equirect (a common 4K 360 video size): sawtooth ramps of periods
/// 36, 85 and 1024 texels, whose 255 -> 0 wraps are worst-case steps for filters. Built once.
const cv::Mat& synthetic_frame();

/// Blender's CC0 `sunrise.exr` (blender-data) as CV_32FC3 RGB with its HDR values, or seeded
/// uniform noise in [0, 1] of the same 1024 x 512 size when the file is missing (then
/// `*from_file` is false). Built once.
const cv::Mat& sunrise_rgb(bool* from_file = nullptr);

/// A size x size CV_32FC3 image of seeded uniform noise in [0, 1].
cv::Mat noise_image(int size);

/// A head at standing height (1.6 m) looking at `look`.
xr::Pose head_at(const effects::Direction& look);

/// The generic90 profile's left eye: panel viewport, FOV and lens (1440 x 1600).
const effects::EyeLens& generic90_left_lens();

/// 4096 panel points of generic90's left eye on a 64 x 64 grid over the whole viewport, in
/// normalised lens coordinates (tangent / R), as OpenCV's undistortPoints takes them.
const std::vector<cv::Point2d>& lens_grid_points();

/// Pixels of generic90's left eye image per normalised lens unit (horizontally).
double lens_px_per_unit();

/// A panel point (normalised lens coordinates) undistorted by generic90's left lens.
cv::Point2d undistort_point(const cv::Point2d& p, effects::InverseMethod method);

/// The peer: OpenCV's iterative undistortion of lens_grid_points() with the same radial model
/// (k1 = c1, k2 = c2, an identity camera matrix); iterations 0: OpenCV's default (5), else up to
/// that many with a 1e-15 tolerance.
void opencv_undistort_grid(std::vector<cv::Point2d>& out, int iterations);

/// Every colour effect active at a moderate setting (tint, exposure, saturation, contrast,
/// vignette), no blur: the colour stack the benchmarks time.
effects::StackParams colour_params();

}  // namespace vdfx::app::bench
