/// @file
/// @brief The video layer with decoded Y'CbCr pictures: the layer's shader converts every sample
/// (matrix, range, chroma siting) and must give what the CPU reference gives (io::to_rgb, then a
/// bilinear sample of the same ray), for every layout the decoder hands over: 4:2:0 with left,
/// centre and top-left siting, 4:2:2, 4:4:4, odd sizes, 10-bit codes, limited and full range,
/// BT.601, BT.709 and BT.2020, padded rows; and packed RGB pictures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "effects/equirect_sampler.h"
#include "gl_test_support.h"
#include "io/ycbcr.h"
#include "xr/render/video_layer.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

/// Colour that varies smoothly in both directions (two cycles across, one down), so a chroma
/// siting off by half a texel shows as a colour shift, while 4:2:0 still resolves it.
cv::Mat test_rgb(int w, int h) {
  cv::Mat m(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float u = (x + 0.5f) / w, v = (y + 0.5f) / h;
      m.at<cv::Vec3f>(y, x) = cv::Vec3f(0.5f + 0.35f * std::sin(6.2832f * (2 * u + v)),
                                        0.5f + 0.3f * std::cos(6.2832f * v),
                                        0.5f + 0.35f * std::sin(6.2832f * (2 * u - v)));
    }
  return m;
}

/// CPU reference: the picture converted by io::to_rgb, sampled bilinearly along every pixel's ray
/// (level 0, rows clamped like GL's CLAMP_TO_EDGE); RGB.
cv::Mat cpu_view(const io::Picture& pic, const RenderView& v, int w, int h) {
  const cv::Mat rgb = io::to_rgb(pic, io::PixelFormat::RgbF32);
  const effects::EquirectSampler s(rgb,
                                   {effects::SampleFilter::Bilinear, effects::PoleRows::Clamp});
  cv::Mat out(h, w, CV_32FC3);
  out.forEach<cv::Vec3f>([&](cv::Vec3f& px, const int* pos) {
    const Eigen::Vector3d c = s.sample(v.world_ray(pos[1] + 0.5, pos[0] + 0.5, w, h));
    px = cv::Vec3f(static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z()));
  });
  return out;
}

cv::Mat gpu_view(VideoLayerGl& layer, const RenderView& v, int w, int h) {
  GlTarget dst(w, h, TexFormat::RGBA32F);
  layer.render(dst, v, LodMode::Base);
  cv::Mat rgb;
  cv::cvtColor(dst.read_float(), rgb, cv::COLOR_BGRA2RGB);
  return rgb;
}

double max_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  return mx;
}

/// 10-bit codes from an 8-bit picture (x 4 plus slowly changing low bits), in 16-bit planes.
io::Picture to_ten_bit(const io::Picture& p8) {
  io::Picture p = p8;
  p.ycbcr.bit_depth = 10;
  for (auto& plane : p.planes) {
    cv::Mat wide;
    plane.convertTo(wide, CV_16UC1, 4.0);
    for (int y = 0; y < wide.rows; ++y)
      for (int x = 0; x < wide.cols; ++x)
        wide.at<std::uint16_t>(y, x) += static_cast<std::uint16_t>((x / 8 + y / 8) % 4);
    plane = wide;
  }
  return p;
}

class VideoLayerPictureGlTest : public GlTest {};

TEST_F(VideoLayerPictureGlTest, ShaderConvertsLikeTheCpuReference) {
  struct Case {
    const char* name;
    int w, h;
    io::YcbcrInfo info;
    bool ten_bit;
  };
  std::vector<Case> cases;
  io::YcbcrInfo i420;  // BT.709 limited, left siting
  cases.push_back({"420 left bt709 limited", 128, 64, i420, false});
  io::YcbcrInfo centre = i420;
  centre.chroma_x = 0.5;
  centre.matrix = io::YcbcrMatrix::Bt601;
  centre.full_range = true;
  cases.push_back({"420 centre bt601 full", 128, 64, centre, false});
  io::YcbcrInfo topleft = i420;
  topleft.chroma_y = 0.0;
  topleft.matrix = io::YcbcrMatrix::Bt2020;
  cases.push_back({"420 top-left bt2020", 128, 64, topleft, false});
  cases.push_back({"420 odd size", 127, 63, i420, false});
  io::YcbcrInfo i422 = i420;
  i422.log2_chroma_h = 0;
  i422.chroma_y = 0.0;
  cases.push_back({"422", 128, 64, i422, false});
  io::YcbcrInfo i444 = i420;
  i444.log2_chroma_w = i444.log2_chroma_h = 0;
  i444.chroma_x = i444.chroma_y = 0.0;
  cases.push_back({"444", 128, 64, i444, false});
  cases.push_back({"420 10-bit bt2020", 128, 64, topleft, true});
  cases.push_back({"420 10-bit full", 128, 64, centre, true});

  // Magnified views (level 0 everywhere), one across the seam.
  const int w = 160, h = 120;
  const RenderView views[] = {RenderView::look_at({20, 10}, 0, 40.0, w, h),
                              RenderView::look_at({178, -20}, 15, 40.0, w, h)};
  VideoLayerGl layer;
  for (const Case& c : cases) {
    io::Picture pic = io::rgb_to_ycbcr(test_rgb(c.w, c.h), c.info);
    if (c.ten_bit) pic = to_ten_bit(pic);
    // Padded rows, as decoders make them: a wider buffer, the picture a view into it.
    for (auto& plane : pic.planes) {
      cv::Mat wide(plane.rows, plane.cols + 13, plane.type(), cv::Scalar(0));
      plane.copyTo(wide(cv::Rect(0, 0, plane.cols, plane.rows)));
      plane = wide(cv::Rect(0, 0, plane.cols, plane.rows));
    }
    layer.set_frame(pic);
    for (const RenderView& v : views) {
      // An odd width has one chroma column more than half its luma columns: the seam cannot
      // line up in both (the GPU repeats the chroma texture's own width); away from it, exact.
      if (c.w % 2 && &v != &views[0]) continue;
      const double e = max_diff(gpu_view(layer, v, w, h), cpu_view(pic, v, w, h));
      std::printf("[ picture  ] %-24s max %.3f/255\n", c.name, e * 255);
      // The GPU filters codes then converts, the CPU converts (chroma upsampled to the luma grid)
      // then filters. With chroma sited on luma columns (left, top-left) the two are the same
      // function; centre siting adds a second-order smoothing on the CPU (1.4/255 here). And
      // llvmpipe returns a filtered R8 texel in 8 bits: one chroma code is up to 2/255 of blue.
      EXPECT_LE(e, (c.ten_bit ? 1.5 : 3.5) / 255.0) << c.name;
    }
  }
}

TEST_F(VideoLayerPictureGlTest, WrongSitingWouldShow) {
  // The test above can see a siting error: the same picture read with its chroma half a luma
  // texel off differs by more than its tolerance.
  io::YcbcrInfo info;
  const io::Picture pic = io::rgb_to_ycbcr(test_rgb(128, 64), info);
  io::Picture shifted = pic;
  shifted.ycbcr.chroma_x = 0.5;
  VideoLayerGl layer;
  layer.set_frame(shifted);
  const RenderView v = RenderView::look_at({20, 10}, 0, 40.0, 160, 120);
  EXPECT_GT(max_diff(gpu_view(layer, v, 160, 120), cpu_view(pic, v, 160, 120)), 4.0 / 255.0);
}

TEST_F(VideoLayerPictureGlTest, PackedRgbPicturesUploadAsTheyAre) {
  VideoLayerGl layer;
  const cv::Mat rgb = test_rgb(30, 17);
  io::Picture p8;
  rgb.convertTo(p8.rgb, CV_8UC3, 255.0);
  layer.set_frame(p8);
  cv::Mat want8, got;
  p8.rgb.convertTo(want8, CV_32FC3, 1.0 / 255.0);
  cv::cvtColor(layer.texture().read_float(), got, cv::COLOR_BGRA2RGB);
  EXPECT_LE(max_diff(got, want8), 1e-6);
  io::Picture pf;
  pf.rgb = rgb;
  layer.set_frame(pf);
  cv::cvtColor(layer.texture().read_float(), got, cv::COLOR_BGRA2RGB);
  EXPECT_LE(max_diff(got, rgb), 1e-6);  // RGBA32F
}

}  // namespace
}  // namespace vdfx::xr
