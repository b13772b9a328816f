/// @file
/// @brief analysis_grey (analysis_frame.h).
#include "app/track/analysis_frame.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "effects/equirect_sampler.h"

namespace vdfx::app::track {

cv::Mat reduce_area(const cv::Mat& image, cv::Size size) {
  cv::Mat current = image;
  while (current.cols / 2 >= size.width && current.rows / 2 >= size.height) {
    cv::Mat half;
    cv::resize(current, half, cv::Size(current.cols / 2, current.rows / 2), 0, 0, cv::INTER_AREA);
    current = half;
  }
  if (current.size() == size) return current.data == image.data ? current.clone() : current;
  cv::Mat out;
  cv::resize(current, out, size, 0, 0, cv::INTER_AREA);
  return out;
}

cv::Mat analysis_grey(const io::Picture& picture, const effects::StereoLayout& layout,
                      cv::Size size) {
  if (picture.empty()) throw std::invalid_argument("analysis_grey: empty picture");
  cv::Mat grey;
  if (picture.is_ycbcr()) {
    grey = effects::eye_image(picture.planes[0], layout, effects::EyeIndex::Left);
  } else {
    const cv::Mat eye = effects::eye_image(picture.rgb, layout, effects::EyeIndex::Left);
    cv::cvtColor(eye, grey, cv::COLOR_RGB2GRAY);
  }
  const cv::Mat small = reduce_area(grey, size);
  if (small.depth() == CV_8U) return small;
  cv::Mat out;
  // 16-bit planes hold bit_depth-bit code values; float RGB is [0, 1].
  const double scale =
      small.depth() == CV_16U ? 255.0 / ((1 << picture.ycbcr.bit_depth) - 1) : 255.0;
  small.convertTo(out, CV_8U, scale);
  return out;
}

}  // namespace vdfx::app::track
