/// @file
/// @brief A decoded picture as a decoder hands it over: packed RGB (stills, RGB codecs) or planar
/// Y'CbCr in the stream's own layout with the colour description needed to convert it.
///
/// Video frames stay Y'CbCr from the decoder to the GPU, which converts them in the video layer
/// (xr/render/video_layer.h); the CPU reference conversion with the same formulas is io/ycbcr.h.
#pragma once

#include <array>
#include <memory>
#include <opencv2/core.hpp>

namespace vdfx::io {

/// Layout of RGB frames handed to consumers that want RGB (FrameDecoder::read, to_rgb): RGB order,
/// display-encoded values (Rgb8: value / 255; RgbF32 in [0, 1]).
enum class PixelFormat { Rgb8, RgbF32 };

/// The Y'CbCr -> R'G'B' matrix (ITU-R BT.601, BT.709, BT.2020 non-constant luminance).
enum class YcbcrMatrix { Bt601, Bt709, Bt2020 };

/// How a Y'CbCr picture's code values are to be read.
struct YcbcrInfo {
  YcbcrMatrix matrix = YcbcrMatrix::Bt709;
  bool full_range = false;  //!< false: limited ("TV", 16..235 for 8 bits); true: full (0..2^n-1)
  int bit_depth = 8;        //!< bits per code value; > 8 is stored LSB-aligned in 16-bit planes
  int log2_chroma_w = 1;    //!< chroma subsampling: 4:2:0 is (1, 1), 4:2:2 (1, 0), 4:4:4 (0, 0)
  int log2_chroma_h = 1;
  /// Position of chroma sample 0 in luma sample units (chroma sample j sits at luma coordinate
  /// j * 2^log2 + offset): 4:2:0 "left" (MPEG-2, H.264, HEVC default) is (0, 0.5), "center"
  /// (JPEG, MPEG-1) (0.5, 0.5), "top-left" (0, 0).
  double chroma_x = 0.0;
  double chroma_y = 0.5;
  bool operator==(const YcbcrInfo&) const = default;
};

struct Picture {
  /// Packed RGB (CV_8UC3 or CV_32FC3, display-encoded values) for RGB pictures; empty otherwise.
  cv::Mat rgb;
  /// Y'CbCr pictures: Y', Cb, Cr planes, CV_8UC1 (bit_depth 8) or CV_16UC1. The chroma planes are
  /// ceil(width / 2^log2_chroma_w) x ceil(height / 2^log2_chroma_h). Rows may be padded (step).
  std::array<cv::Mat, 3> planes;
  YcbcrInfo ycbcr;
  /// Keeps the decoder's buffers alive while the planes point into them (no copy between the
  /// decoder and the upload). Copy the Picture, not only the plane headers.
  std::shared_ptr<const void> owner;

  bool is_ycbcr() const { return !planes[0].empty(); }
  bool empty() const { return rgb.empty() && planes[0].empty(); }
  int width() const { return is_ycbcr() ? planes[0].cols : rgb.cols; }
  int height() const { return is_ycbcr() ? planes[0].rows : rgb.rows; }
};

}  // namespace vdfx::io
