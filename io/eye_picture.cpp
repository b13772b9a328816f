/// @file
/// @brief cut_picture, to_rgb_by_eye and rgb_to_ycbcr_by_eye (see eye_picture.h).
#include "io/eye_picture.h"

#include <array>
#include <optional>

#include "io/ycbcr.h"

namespace vdfx::io {
namespace {

cv::Rect rect_of(const effects::PixelRect& r) {
  return {r.x, r.y, r.width, r.height};
}

bool on_chroma_grid(const effects::PixelRect& r, int log2_w, int log2_h) {
  const int mx = (1 << log2_w) - 1, my = (1 << log2_h) - 1;
  return !((r.x & mx) || (r.y & my) || (r.width & mx) || (r.height & my));
}

/// The eyes' rectangles of a `width` x `height` frame when `layout` is stereo and both fall on
/// the chroma grid; none otherwise (the frame is converted as one image).
std::optional<std::array<effects::PixelRect, 2>> eye_rects(const effects::StereoLayout& layout,
                                                           int width, int height, int log2_w,
                                                           int log2_h) {
  if (!layout.stereo()) return std::nullopt;
  std::array<effects::PixelRect, 2> rects;
  for (std::size_t i = 0; i < 2; ++i) {
    rects[i] = effects::eye_rect(layout, static_cast<effects::EyeIndex>(i), width, height);
    if (!on_chroma_grid(rects[i], log2_w, log2_h)) return std::nullopt;
  }
  return rects;
}

}  // namespace

bool cut_picture(const Picture& pic, const effects::PixelRect& r, Picture& out) {
  if (!pic.is_ycbcr()) {
    out = pic;
    out.rgb = pic.rgb(rect_of(r));
    return true;
  }
  const int sx = pic.ycbcr.log2_chroma_w, sy = pic.ycbcr.log2_chroma_h;
  if (!on_chroma_grid(r, sx, sy)) return false;
  out = pic;
  out.planes[0] = pic.planes[0](rect_of(r));
  for (std::size_t i = 1; i < 3; ++i)
    out.planes[i] = pic.planes[i](cv::Rect(r.x >> sx, r.y >> sy, r.width >> sx, r.height >> sy));
  return true;
}

void to_rgb_by_eye(const Picture& pic, const effects::StereoLayout& layout, PixelFormat format,
                   cv::Mat& out) {
  const bool wrap = layout.coverage_deg == 360;
  const auto rects = pic.is_ycbcr() ? eye_rects(layout, pic.width(), pic.height(),
                                                pic.ycbcr.log2_chroma_w, pic.ycbcr.log2_chroma_h)
                                    : std::nullopt;
  if (!rects) return to_rgb(pic, format, out, wrap);
  out.create(pic.height(), pic.width(), format == PixelFormat::Rgb8 ? CV_8UC3 : CV_32FC3);
  for (const effects::PixelRect& r : *rects) {
    Picture half;
    cut_picture(pic, r, half);
    cv::Mat eye = out(rect_of(r));  // converted in place: the header has its size and type
    to_rgb(half, format, eye, wrap);
  }
}

cv::Mat to_rgb_by_eye(const Picture& pic, const effects::StereoLayout& layout, PixelFormat format) {
  cv::Mat out;
  to_rgb_by_eye(pic, layout, format, out);
  return out;
}

Picture rgb_to_ycbcr_by_eye(const cv::Mat& rgb, const YcbcrInfo& info,
                            const effects::StereoLayout& layout) {
  const auto rects = eye_rects(layout, rgb.cols, rgb.rows, info.log2_chroma_w, info.log2_chroma_h);
  if (!rects) return rgb_to_ycbcr(rgb, info);
  Picture out;
  out.ycbcr = info;
  const int type = info.bit_depth > 8 ? CV_16UC1 : CV_8UC1;
  const int sx = info.log2_chroma_w, sy = info.log2_chroma_h;
  out.planes[0].create(rgb.rows, rgb.cols, type);
  for (std::size_t i = 1; i < 3; ++i) out.planes[i].create(rgb.rows >> sy, rgb.cols >> sx, type);
  for (const effects::PixelRect& r : *rects) {
    const Picture eye = rgb_to_ycbcr(rgb(rect_of(r)), info);
    Picture dst;
    cut_picture(out, r, dst);  // views into out's planes
    for (std::size_t i = 0; i < 3; ++i) eye.planes[i].copyTo(dst.planes[i]);
  }
  return out;
}

}  // namespace vdfx::io
