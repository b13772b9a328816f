/// @file
/// @brief A decoded stereo frame eye by eye (docs/stereo.md): one eye's planes cut on the chroma
/// grid (what the GL video layer uploads per eye), and the CPU reference's conversion of a
/// frame in which no eye's chroma is interpolated with the other eye's.
#pragma once

#include "effects/stereo_layout.h"
#include "io/picture.h"

namespace vdfx::io {

/// `picture` cut to the pixel rectangle `r`: Y'CbCr planes as views (no copy), the chroma
/// planes cut at the subsampled rectangle; an RGB picture's pixels likewise. False, leaving
/// `out` as it was, when `r` does not fall on the chroma grid (an odd half height in 4:2:0).
bool cut_picture(const Picture& picture, const effects::PixelRect& r, Picture& out);

/// The CPU reference conversion (io::to_rgb) of a frame shown with `layout`: each eye's
/// rectangle converted from its own planes alone, so chroma upsampling never mixes the two
/// eyes at the boundary between the halves; within an eye's image the columns' chroma wraps
/// at a 360 image's seam and is clamped at a VR180 image's edges, as the GL video layer
/// samples the planes. A layout whose halves do not fall on the chroma grid is converted as
/// one frame (the GL layer then converts on the CPU too). The layout must divide the frame.
cv::Mat to_rgb_by_eye(const Picture& picture, const effects::StereoLayout& layout,
                      PixelFormat format);
/// The same into `out`, whose buffer is reused when it has the size and type already.
void to_rgb_by_eye(const Picture& picture, const effects::StereoLayout& layout, PixelFormat format,
                   cv::Mat& out);

/// The encoder's conversion (io::rgb_to_ycbcr) of a frame holding `layout`'s eyes: each eye's
/// half encoded on its own, so no chroma sample averages R'G'B' from both sides of the boundary
/// between the halves (the tent filter clamped at each half's edges as at the frame's). Mono,
/// or halves off the chroma grid: rgb_to_ycbcr of the whole frame.
Picture rgb_to_ycbcr_by_eye(const cv::Mat& rgb, const YcbcrInfo& info,
                            const effects::StereoLayout& layout);

}  // namespace vdfx::io
