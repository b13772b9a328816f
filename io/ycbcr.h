/// @file
/// @brief Y'CbCr <-> R'G'B' conversion: the formulas the GPU uses (xr/render/video_layer.cpp) and
/// the CPU reference path (export, `vdfx render`, tests).
///
/// ITU-R BT.601 / BT.709 / BT.2020 (non-constant luminance) with luma weights Kr, Kb
/// (Kg = 1 - Kr - Kb), and the code ranges of ITU-T H.273 for n-bit codes:
///   limited: E'Y = (Y - 16 * 2^(n-8)) / (219 * 2^(n-8)),  E'C = (C - 2^(n-1)) / (224 * 2^(n-8))
///   full:    E'Y = Y / (2^n - 1),                          E'C = (C - 2^(n-1)) / (2^n - 1)
///   R' = E'Y + 2 (1 - Kr) E'Cr,  B' = E'Y + 2 (1 - Kb) E'Cb,  G' = (E'Y - Kr R' - Kb B') / Kg
/// Both together are one affine map of the code values (ycbcr_to_rgb_map), clamped to [0, 1]
/// only after it. Chroma is upsampled bilinearly at the stream's chroma siting: luma pixel x reads
/// chroma at c = (x - chroma_x) / 2^log2_chroma_w (in chroma samples, clamped at the edges), the
/// same coordinate the GPU's linear sampler gets (texel centre c + 0.5).
#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "io/picture.h"

namespace vdfx::io {

struct LumaWeights {
  double kr = 0.0, kb = 0.0;
  double kg() const { return 1.0 - kr - kb; }
};
LumaWeights luma_weights(YcbcrMatrix matrix);

/// rgb = m * (Y, Cb, Cr) + offset, with Y, Cb, Cr the integer code values (row-major m).
struct AffineMap3 {
  std::array<double, 9> m{};
  std::array<double, 3> offset{};
  std::array<double, 3> apply(double a, double b, double c) const {
    return {m[0] * a + m[1] * b + m[2] * c + offset[0], m[3] * a + m[4] * b + m[5] * c + offset[1],
            m[6] * a + m[7] * b + m[8] * c + offset[2]};
  }
};

/// Code values -> R'G'B' (unclamped).
AffineMap3 ycbcr_to_rgb_map(const YcbcrInfo& info);
/// R'G'B' -> code values (unrounded): the exact inverse of ycbcr_to_rgb_map.
AffineMap3 rgb_to_ycbcr_map(const YcbcrInfo& info);

/// The CPU reference conversion: a picture (Y'CbCr or RGB) as RGB in `format`, clamped to [0, 1]
/// (8-bit: rounded to nearest). An RGB picture is only converted to `format`.
cv::Mat to_rgb(const Picture& picture, PixelFormat format);
/// The same into `out`, whose buffer is reused when it has the size and type already.
/// `wrap_columns`: chroma is interpolated across the seam between the last and the first column
/// (a 360 image); false clamps it at the edges (a VR180 image; io/eye_picture.h).
void to_rgb(const Picture& picture, PixelFormat format, cv::Mat& out, bool wrap_columns = true);

/// Encodes an RGB image (CV_32FC3 in [0, 1], clamped first, or CV_8UC3) as a Y'CbCr picture in
/// `info`'s layout (bit_depth 8, or 10 in 16-bit planes): luma per pixel, chroma from R'G'B'
/// averaged over each chroma sample's footprint with a tent filter centred on its siting
/// (half-width one subsampling step), codes rounded to nearest.
Picture rgb_to_ycbcr(const cv::Mat& rgb, const YcbcrInfo& info);

}  // namespace vdfx::io
