/// @file
/// @brief Still images (PNG, JPEG, EXR, Radiance HDR, and whatever else OpenCV reads) as RGB
/// CV_32FC3 with display-encoded values in [0, 1], the values the effects act on.
///
/// 8- and 16-bit images are already sRGB-encoded: they are scaled to [0, 1] as stored. Float
/// images (EXR, HDR) hold linear radiance: they are tone-mapped (io/tone_map.h). Grey images are
/// repeated to three channels; an alpha channel is dropped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

#include "io/tone_map.h"

namespace vdfx::io {

/// Sets OPENCV_IO_ENABLE_OPENEXR=1 once per process. OpenCV reads the variable once, at its
/// first EXR access, so this must run before any EXR is read or written (load_image calls it;
/// code that writes EXR itself calls it first).
void enable_openexr();

/// True for file names whose extension load_image takes as a still image (.png, .jpg, .jpeg,
/// .exr, .hdr, .pic, .tif, .tiff, .bmp, .webp; case-insensitive).
bool is_still_image_path(const std::filesystem::path& path);

/// The largest frame vdfx takes as an input, still or video (docs/reliability.md, "Limits"):
/// each side at most 16384 (the largest texture common GL implementations take) and at most
/// 2^27 pixels (16384x8192, an equirect of 16K): about 1.6 GiB as float RGB.
inline constexpr int kMaxFrameSide = 16384;
inline constexpr std::int64_t kMaxFramePixels = std::int64_t{1} << 27;

/// Throws io::InputError naming `file`, its size and the limit when a frame of width x height is
/// beyond kMaxFrameSide / kMaxFramePixels.
void check_frame_size(const std::string& file, int width, int height);

struct LoadedImage {
  cv::Mat rgb;               //!< CV_32FC3, RGB order, display-encoded, [0, 1]
  bool tone_mapped = false;  //!< true when the file held linear float radiance
  int source_depth = 0;      //!< OpenCV depth of the file's samples (CV_8U, CV_16U, CV_32F)
};

/// Loads a still image. Throws io::InputError naming the file and the reason when it is missing,
/// not a file, or cannot be decoded.
LoadedImage load_image(const std::filesystem::path& path, const ToneMapSettings& tone = {});

/// Converts an image as OpenCV decoded it (BGR or BGRA or grey, any depth) to LoadedImage.
LoadedImage to_display_rgb(const cv::Mat& decoded, const ToneMapSettings& tone = {});

}  // namespace vdfx::io
