/// @file
/// @brief Differences of float images in 8-bit steps.
#include "app/bench/error.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace vdfx::app::bench {

ErrorStats steps_error(const cv::Mat& a, const cv::Mat& b, double* mean) {
  const auto bgr = [](const cv::Mat& m) {
    cv::Mat out;
    if (m.channels() == 4)
      cv::cvtColor(m, out, cv::COLOR_BGRA2BGR);
    else
      out = m;
    out.convertTo(out, CV_64FC3);
    cv::min(cv::max(out, 0.0), 1.0, out);
    return out;
  };
  cv::Mat d;
  cv::absdiff(bgr(a), bgr(b), d);
  d *= 255.0;
  double mx = 0.0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  const double n = static_cast<double>(d.total() * 3);
  const double rms = std::sqrt(d.dot(d) / n);
  if (mean) *mean = cv::sum(d)[0] / n + cv::sum(d)[1] / n + cv::sum(d)[2] / n;
  return {mx, rms};
}

}  // namespace vdfx::app::bench
