/// @file
/// @brief The CPU Y'CbCr conversions against their definitions in io/ycbcr.h, written out per
/// sample in double precision: encoding (luma per pixel, chroma the tent-filtered R'G'B' at each
/// chroma sample's siting, edges clamped) and decoding (chroma bilinear at the siting, columns
/// wrapping, rows clamped), over the chroma layouts and odd sizes the fast row loops special-case.
#include "io/ycbcr.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vdfx::io {
namespace {

struct Layout {
  int log2_w, log2_h;
  double x, y;
  const char* name;
};

const Layout kLayouts[] = {{1, 1, 0.0, 0.5, "420 left"},
                           {1, 1, 0.5, 0.5, "420 center"},
                           {1, 1, 0.0, 0.0, "420 top-left"},
                           {1, 0, 0.0, 0.0, "422"},
                           {0, 0, 0.0, 0.0, "444"}};

YcbcrInfo info_of(const Layout& l, bool full_range) {
  YcbcrInfo i;
  i.log2_chroma_w = l.log2_w;
  i.log2_chroma_h = l.log2_h;
  i.chroma_x = l.x;
  i.chroma_y = l.y;
  i.full_range = full_range;
  return i;
}

cv::Mat test_image(int w, int h) {
  cv::Mat m(h, w, CV_32FC3);
  cv::randu(m, -0.1, 1.1);  // some values outside [0, 1]: the encoder clamps them first
  return m;
}

/// Normalised tent weights of chroma sample j along one axis of n samples (edges clamped).
std::vector<double> tent(int j, int n, int log2_sub, double siting) {
  const double step = std::ldexp(1.0, log2_sub), centre = j * step + siting;
  std::vector<double> w(static_cast<std::size_t>(n), 0.0);
  double sum = 0.0;
  for (int x = static_cast<int>(std::ceil(centre - step)); x <= centre + step; ++x) {
    const double k = 1.0 - std::abs(x - centre) / step;
    if (k <= 0.0) continue;
    w[static_cast<std::size_t>(std::clamp(x, 0, n - 1))] += k;
    sum += k;
  }
  for (double& k : w) k /= sum;
  return w;
}

TEST(Ycbcr, EncodingFollowsTheTentFilterDefinitionInEveryLayout) {
  for (const Layout& l : kLayouts)
    for (const bool full : {false, true})
      for (const cv::Size size : {cv::Size(64, 32), cv::Size(37, 23)}) {
        const YcbcrInfo info = info_of(l, full);
        const cv::Mat rgb = test_image(size.width, size.height);
        const Picture p = rgb_to_ycbcr(rgb, info);
        const AffineMap3 a = rgb_to_ycbcr_map(info);
        const std::string what = std::string(l.name) + (full ? " full " : " limited ") +
                                 std::to_string(size.width) + "x" + std::to_string(size.height);
        auto clamped = [&](int y, int x, int c) {
          return std::clamp(static_cast<double>(rgb.at<cv::Vec3f>(y, x)[c]), 0.0, 1.0);
        };
        int worst = 0;
        for (int y = 0; y < size.height; ++y)
          for (int x = 0; x < size.width; ++x) {
            const auto code = a.apply(clamped(y, x, 0), clamped(y, x, 1), clamped(y, x, 2));
            worst = std::max(worst, std::abs(p.planes[0].at<std::uint8_t>(y, x) -
                                             static_cast<int>(std::lround(code[0]))));
          }
        for (int i = 0; i < p.planes[1].rows; ++i)
          for (int j = 0; j < p.planes[1].cols; ++j) {
            const auto wy = tent(i, size.height, l.log2_h, l.y);
            const auto wx = tent(j, size.width, l.log2_w, l.x);
            double avg[3] = {0, 0, 0};
            for (int y = 0; y < size.height; ++y)
              for (int x = 0; x < size.width; ++x)
                for (int c = 0; c < 3; ++c)
                  avg[c] += wy[static_cast<std::size_t>(y)] * wx[static_cast<std::size_t>(x)] *
                            clamped(y, x, c);
            const auto code = a.apply(avg[0], avg[1], avg[2]);
            for (int c = 1; c < 3; ++c)
              worst = std::max(worst, std::abs(p.planes[c].at<std::uint8_t>(i, j) -
                                               static_cast<int>(std::lround(code[c]))));
          }
        // Float sums against double ones: a code may round the other way at a half.
        EXPECT_LE(worst, 1) << what;
      }
}

TEST(Ycbcr, DecodingIsBilinearChromaAtTheSitingInEveryLayout) {
  for (const Layout& l : kLayouts)
    for (const cv::Size size : {cv::Size(64, 32), cv::Size(37, 23)}) {
      const YcbcrInfo info = info_of(l, false);
      const Picture p = rgb_to_ycbcr(test_image(size.width, size.height), info);
      const cv::Mat f = to_rgb(p, PixelFormat::RgbF32), b = to_rgb(p, PixelFormat::Rgb8);
      const AffineMap3 a = ycbcr_to_rgb_map(info);
      const int cw = p.planes[1].cols, ch = p.planes[1].rows;
      double worst_f = 0.0;
      int worst_b = 0;
      for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
          const double cx = (x - l.x) / (1 << l.log2_w), cy = (y - l.y) / (1 << l.log2_h);
          const int x0 = static_cast<int>(std::floor(cx)), y0 = static_cast<int>(std::floor(cy));
          const double tx = cx - x0, ty = cy - y0;
          const int xa = ((x0 % cw) + cw) % cw, xb = (xa + 1) % cw;  // azimuth wraps
          const int ya = std::clamp(y0, 0, ch - 1), yb = std::clamp(y0 + 1, 0, ch - 1);
          auto chroma = [&](int plane) {
            const cv::Mat& m = p.planes[plane];
            const double top =
                m.at<std::uint8_t>(ya, xa) * (1 - tx) + m.at<std::uint8_t>(ya, xb) * tx;
            const double bottom =
                m.at<std::uint8_t>(yb, xa) * (1 - tx) + m.at<std::uint8_t>(yb, xb) * tx;
            return top * (1 - ty) + bottom * ty;
          };
          const auto rgb = a.apply(p.planes[0].at<std::uint8_t>(y, x), chroma(1), chroma(2));
          for (int c = 0; c < 3; ++c) {
            const double want = std::clamp(rgb[c], 0.0, 1.0);
            worst_f = std::max(worst_f, std::abs(f.at<cv::Vec3f>(y, x)[c] - want));
            worst_b = std::max(worst_b, std::abs(b.at<cv::Vec3b>(y, x)[c] -
                                                 static_cast<int>(std::lround(want * 255.0))));
          }
        }
      EXPECT_LT(worst_f, 1e-5) << l.name << " " << size.width << "x" << size.height;
      EXPECT_LE(worst_b, 1) << l.name << " " << size.width << "x" << size.height;
    }
}

}  // namespace
}  // namespace vdfx::io
