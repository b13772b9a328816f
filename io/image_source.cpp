/// @file
/// @brief load_image: OpenCV imread, channel and depth normalisation, tone mapping of radiance.
#include "io/image_source.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "io/input_error.h"
#include "io/input_file.h"

namespace vdfx::io {

void enable_openexr() {
  static std::once_flag once;
  std::call_once(once, [] { ::setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1); });
}

bool is_still_image_path(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  static const std::array<const char*, 10> kExt = {".png", ".jpg", ".jpeg", ".exr", ".hdr",
                                                   ".pic", ".tif", ".tiff", ".bmp", ".webp"};
  return std::find(kExt.begin(), kExt.end(), ext) != kExt.end();
}

LoadedImage to_display_rgb(const cv::Mat& decoded, const ToneMapSettings& tone) {
  if (decoded.empty()) throw std::invalid_argument("to_display_rgb: empty image");
  cv::Mat bgr;
  switch (decoded.channels()) {
    case 1: cv::cvtColor(decoded, bgr, cv::COLOR_GRAY2BGR); break;
    case 3: bgr = decoded; break;
    case 4: cv::cvtColor(decoded, bgr, cv::COLOR_BGRA2BGR); break;
    default:
      throw std::invalid_argument("to_display_rgb: " + std::to_string(decoded.channels()) +
                                  " channels");
  }
  LoadedImage out;
  out.source_depth = decoded.depth();
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  switch (decoded.depth()) {
    case CV_8U: rgb.convertTo(out.rgb, CV_32FC3, 1.0 / 255.0); break;
    case CV_16U: rgb.convertTo(out.rgb, CV_32FC3, 1.0 / 65535.0); break;
    case CV_32F:
    case CV_64F:
    case CV_16F: {
      cv::Mat linear;
      rgb.convertTo(linear, CV_32FC3);
      out.rgb = tone_map_reinhard(linear, tone);
      out.tone_mapped = true;
      break;
    }
    default:
      throw std::invalid_argument("to_display_rgb: unsupported sample depth " +
                                  std::to_string(decoded.depth()));
  }
  return out;
}

void check_frame_size(const std::string& file, int width, int height) {
  if (width > kMaxFrameSide || height > kMaxFrameSide ||
      std::int64_t{width} * height > kMaxFramePixels)
    throw InputError(file + ": the image is " + std::to_string(width) + "x" +
                     std::to_string(height) + "; vdfx takes frames of at most " +
                     std::to_string(kMaxFrameSide) + " pixels per side and " +
                     std::to_string(kMaxFramePixels) + " pixels in all (16384x8192)");
}

LoadedImage load_image(const std::filesystem::path& path, const ToneMapSettings& tone) {
  const std::string name = path.string();
  // A regular file only: OpenCV would block forever on a named pipe with no writer.
  check_input_file(path, std::numeric_limits<std::uintmax_t>::max(), "an image");
  if (!std::ifstream(path, std::ios::binary)) throw InputError(name + ": cannot open for reading");
  enable_openexr();
  cv::Mat decoded;
  try {
    decoded = cv::imread(name, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw InputError(name + ": cannot decode image: " + e.what());
  }
  if (decoded.empty())
    throw InputError(name + ": cannot decode image (not a format OpenCV reads, or corrupt)");
  // OpenCV 4.6 cannot report the size without decoding; its own limit (2^30 pixels) bounds the
  // decode, and the check comes before the float copy, the largest allocation.
  check_frame_size(name, decoded.cols, decoded.rows);
  try {
    return to_display_rgb(decoded, tone);
  } catch (const std::invalid_argument& e) {
    throw InputError(name + ": " + e.what());
  }
}

}  // namespace vdfx::io
