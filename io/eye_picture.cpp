/// @file
/// @brief cut_picture and to_rgb_by_eye (see eye_picture.h).
#include "io/eye_picture.h"

#include <array>

#include "io/ycbcr.h"

namespace vdfx::io {

bool cut_picture(const Picture& pic, const effects::PixelRect& r, Picture& out) {
  const cv::Rect rect(r.x, r.y, r.width, r.height);
  if (!pic.is_ycbcr()) {
    out = pic;
    out.rgb = pic.rgb(rect);
    return true;
  }
  const int sx = pic.ycbcr.log2_chroma_w, sy = pic.ycbcr.log2_chroma_h;
  const int mx = (1 << sx) - 1, my = (1 << sy) - 1;
  if ((r.x & mx) || (r.y & my) || (r.width & mx) || (r.height & my)) return false;
  out = pic;
  out.planes[0] = pic.planes[0](rect);
  for (std::size_t i = 1; i < 3; ++i)
    out.planes[i] = pic.planes[i](cv::Rect(r.x >> sx, r.y >> sy, r.width >> sx, r.height >> sy));
  return true;
}

cv::Mat to_rgb_by_eye(const Picture& pic, const effects::StereoLayout& layout, PixelFormat format) {
  const bool wrap = layout.coverage_deg == 360;
  cv::Mat out;
  if (!pic.is_ycbcr() || !layout.stereo()) {
    to_rgb(pic, format, out, wrap);
    return out;
  }
  std::array<Picture, 2> halves;
  std::array<effects::PixelRect, 2> rects;
  for (std::size_t i = 0; i < 2; ++i) {
    rects[i] =
        effects::eye_rect(layout, static_cast<effects::EyeIndex>(i), pic.width(), pic.height());
    if (!cut_picture(pic, rects[i], halves[i])) {
      to_rgb(pic, format, out, wrap);
      return out;
    }
  }
  out.create(pic.height(), pic.width(), format == PixelFormat::Rgb8 ? CV_8UC3 : CV_32FC3);
  for (std::size_t i = 0; i < 2; ++i) {
    cv::Mat eye = out(cv::Rect(rects[i].x, rects[i].y, rects[i].width, rects[i].height));
    cv::Mat converted;
    to_rgb(halves[i], format, converted, wrap);
    converted.copyTo(eye);
  }
  return out;
}

}  // namespace vdfx::io
