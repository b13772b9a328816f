/// @file
/// @brief A whole equirect turned by a rotation (the stabilised export, docs/export.md): every
/// output pixel's direction c shows the source at r^T c, sampled bilinearly. Exact per pixel (two
/// arctangents each, rows in parallel): the export writes these pixels, so no interpolated map.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace vdfx::effects {

/// `out` (same size and type as `src`, any channel count) shows `src` turned: the pixel at
/// direction c samples `src` at direction r^T c. `coverage_deg` is the azimuth the image spans
/// (360: columns wrap; 180, one eye of VR180: directions outside it are black). `out` must not
/// be `src`.
void rotate_equirect(const cv::Mat& src, const Eigen::Matrix3d& r, cv::Mat& out,
                     int coverage_deg = 360);

}  // namespace vdfx::effects
