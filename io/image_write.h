/// @file
/// @brief Writing a PNG the safe way: encoded in memory, then io::write_file_atomic (no half
/// image on a full disk or a crash; links written through; devices and pipes refused).
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>

#include "io/output_path.h"

namespace vdfx::io {

/// Encodes `bgr8` (CV_8UC3 BGR, or anything cv::imencode takes) as PNG and writes it atomically.
/// Throws io::InputError naming `path` when it cannot be written.
/// `name`: see io/output_path.h (links followed for names the user gave, refused for generated).
void write_png(const std::filesystem::path& path, const cv::Mat& bgr8,
               OutputName name = OutputName::Given);

}  // namespace vdfx::io
