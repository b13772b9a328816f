/// @file
/// @brief write_png: cv::imencode, then write_file_atomic.
#include "io/image_write.h"

#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "io/atomic_file.h"

namespace vdfx::io {

void write_png(const std::filesystem::path& path, const cv::Mat& bgr8, OutputName name) {
  std::vector<unsigned char> png;
  // An image OpenCV cannot encode is the caller's bug, not the user's input.
  if (!cv::imencode(".png", bgr8, png))
    throw std::runtime_error("PNG encoding failed for " + path.string());
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()),
                    name);
}

}  // namespace vdfx::io
