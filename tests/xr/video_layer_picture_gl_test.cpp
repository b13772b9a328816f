/// @file
/// @brief The video layer's Y'CbCr -> RGB conversion on the GPU against the CPU reference
/// (io::to_rgb) for every layout the decoder hands over: 4:2:0 with left, centre and top-left
/// chroma siting, 4:2:2, 4:4:4, odd sizes, 10-bit codes, limited and full range, BT.601, BT.709
/// and BT.2020, padded rows; and packed RGB pictures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gl_test_support.h"
#include "io/ycbcr.h"
#include "xr/video_layer.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

/// Smooth and edged content (RGB float): gradients, a sine and hard-edged blocks, so chroma
/// siting errors show.
cv::Mat test_rgb(int w, int h) {
  cv::Mat m(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float u = static_cast<float>(x) / w, v = static_cast<float>(y) / h;
      const bool block = ((x / 5) + (y / 3)) % 4 == 0;
      m.at<cv::Vec3f>(y, x) = block ? cv::Vec3f(0.9f, 0.1f, 0.2f)
                                    : cv::Vec3f(u, v, 0.5f + 0.4f * std::sin(9.0f * u + 4.0f * v));
    }
  return m;
}

/// The layer's level 0 as RGB float (the texture is RGBA, read back BGRA).
cv::Mat layer_rgb(const VideoLayerGl& layer) {
  cv::Mat bgra = layer.texture().read_float(), rgb;
  cv::cvtColor(bgra, rgb, cv::COLOR_BGRA2RGB);
  return rgb;
}

double max_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  return mx;
}

/// 10-bit codes from an 8-bit picture (x 4 plus a ramp in the low bits), in 16-bit planes.
io::Picture to_ten_bit(const io::Picture& p8) {
  io::Picture p = p8;
  p.ycbcr.bit_depth = 10;
  for (auto& plane : p.planes) {
    cv::Mat wide;
    plane.convertTo(wide, CV_16UC1, 4.0);
    for (int y = 0; y < wide.rows; ++y)
      for (int x = 0; x < wide.cols; ++x) wide.at<std::uint16_t>(y, x) += static_cast<std::uint16_t>((x + y) % 4);
    plane = wide;
  }
  return p;
}

class VideoLayerPictureGlTest : public GlTest {};

TEST_F(VideoLayerPictureGlTest, YcbcrConvertsLikeTheCpuReference) {
  struct Case {
    const char* name;
    int w, h;
    io::YcbcrInfo info;
    bool ten_bit;
  };
  std::vector<Case> cases;
  io::YcbcrInfo i420;  // BT.709 limited, left siting
  cases.push_back({"420 left bt709 limited", 64, 32, i420, false});
  io::YcbcrInfo centre = i420;
  centre.chroma_x = 0.5;
  centre.matrix = io::YcbcrMatrix::Bt601;
  centre.full_range = true;
  cases.push_back({"420 centre bt601 full", 64, 32, centre, false});
  io::YcbcrInfo topleft = i420;
  topleft.chroma_y = 0.0;
  topleft.matrix = io::YcbcrMatrix::Bt2020;
  cases.push_back({"420 top-left bt2020", 64, 32, topleft, false});
  cases.push_back({"420 odd size", 37, 23, i420, false});
  io::YcbcrInfo i422 = i420;
  i422.log2_chroma_h = 0;
  i422.chroma_y = 0.0;
  cases.push_back({"422 odd width", 45, 20, i422, false});
  io::YcbcrInfo i444 = i420;
  i444.log2_chroma_w = i444.log2_chroma_h = 0;
  i444.chroma_x = i444.chroma_y = 0.0;
  cases.push_back({"444", 40, 20, i444, false});
  cases.push_back({"420 10-bit bt2020", 64, 32, topleft, true});
  io::YcbcrInfo full10 = centre;
  cases.push_back({"420 10-bit full", 38, 21, full10, true});

  VideoLayerGl layer;
  for (const Case& c : cases) {
    const cv::Mat rgb = test_rgb(c.w, c.h);
    io::Picture pic = io::rgb_to_ycbcr(rgb, c.info);
    if (c.ten_bit) pic = to_ten_bit(pic);
    // Padded rows, as decoders make them: a wider buffer, the picture a view into it.
    for (auto& plane : pic.planes) {
      cv::Mat wide(plane.rows, plane.cols + 13, plane.type(), cv::Scalar(0));
      plane.copyTo(wide(cv::Rect(0, 0, plane.cols, plane.rows)));
      plane = wide(cv::Rect(0, 0, plane.cols, plane.rows));
    }
    layer.set_frame(pic);
    const cv::Mat gpu = layer_rgb(layer);
    const cv::Mat cpu = io::to_rgb(pic, io::PixelFormat::RgbF32);
    ASSERT_EQ(gpu.size(), cpu.size()) << c.name;
    // 8-bit video: the RGBA8 texture's rounding (half a step) plus float differences; deeper
    // video goes to RGBA16F (11-bit mantissa).
    EXPECT_LE(max_diff(gpu, cpu), (c.ten_bit ? 0.75 : 0.51) / 255.0) << c.name;
    EXPECT_EQ(layer.texture().format(), c.ten_bit ? TexFormat::RGBA16F : TexFormat::RGBA8) << c.name;
    // The conversion itself is right too: a smooth image (no block edges, whose chroma 4:2:0
    // cannot keep) comes back within about a code value.
    if (!c.ten_bit) {
      cv::Mat smooth = test_rgb(c.w, c.h);
      for (int y = 0; y < c.h; ++y)
        for (int x = 0; x < c.w; ++x) {
          const float u = static_cast<float>(x) / c.w, v = static_cast<float>(y) / c.h;
          smooth.at<cv::Vec3f>(y, x) = cv::Vec3f(0.1f + 0.8f * u, 0.2f + 0.6f * v, 0.5f + 0.3f * std::sin(3.0f * u));
        }
      layer.set_frame(io::rgb_to_ycbcr(smooth, c.info));
      cv::Mat d;
      cv::absdiff(layer_rgb(layer), smooth, d);
      EXPECT_LT(std::max({cv::mean(d)[0], cv::mean(d)[1], cv::mean(d)[2]}), 1.5 / 255.0) << c.name;
    }
  }
}

TEST_F(VideoLayerPictureGlTest, PackedRgbPicturesUploadAsTheyAre) {
  VideoLayerGl layer;
  const cv::Mat rgb = test_rgb(30, 17);
  io::Picture p8;
  rgb.convertTo(p8.rgb, CV_8UC3, 255.0);
  layer.set_frame(p8);
  cv::Mat want8;
  p8.rgb.convertTo(want8, CV_32FC3, 1.0 / 255.0);
  EXPECT_LE(max_diff(layer_rgb(layer), want8), 1e-6);
  io::Picture pf;
  pf.rgb = rgb;
  layer.set_frame(pf);
  EXPECT_LE(max_diff(layer_rgb(layer), rgb), 1e-3);  // RGBA16F
}

}  // namespace
}  // namespace vdfx::xr
