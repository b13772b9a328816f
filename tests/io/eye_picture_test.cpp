/// @file
/// @brief io/eye_picture.h: a stereo frame's eyes cut on the chroma grid and converted each from
/// its own planes, so that chroma upsampling never mixes the eyes at the boundary between the
/// halves (nor wraps a VR180 image's edges into each other), as the GL video layer samples them;
/// and encoded each from its own half.
#include "io/eye_picture.h"

#include <gtest/gtest.h>

#include "io/ycbcr.h"

namespace vdfx::io {
namespace {

using effects::StereoLayout;
using effects::StereoMode;

/// An 8-bit 4:2:0 picture (left-sited chroma, full range) of constant luma whose chroma is
/// `chroma(cx, cy)` = {Cb, Cr} at chroma sample (cx, cy).
template <typename F>
Picture picture(int w, int h, F chroma) {
  Picture p;
  p.ycbcr.full_range = true;
  p.planes[0] = cv::Mat(h, w, CV_8UC1, cv::Scalar(128));
  p.planes[1] = cv::Mat((h + 1) / 2, (w + 1) / 2, CV_8UC1);
  p.planes[2] = p.planes[1].clone();
  for (int y = 0; y < p.planes[1].rows; ++y)
    for (int x = 0; x < p.planes[1].cols; ++x) {
      const cv::Vec2b c = chroma(x, y);
      p.planes[1].at<uchar>(y, x) = c[0];
      p.planes[2].at<uchar>(y, x) = c[1];
    }
  return p;
}

/// Every pixel of `m` equals its first.
bool uniform(const cv::Mat& m) {
  const cv::Vec3b first = m.at<cv::Vec3b>(0, 0);
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      if (m.at<cv::Vec3b>(y, x) != first) return false;
  return true;
}

// Each eye one colour: converted eye by eye every pixel of a half has its eye's colour; converted
// as one frame, the last column before the boundary (odd luma columns interpolate the chroma
// sample after them) is mixed with the other eye's colour.
TEST(EyePicture, NoEyesChromaIsMixedWithTheOthers) {
  const cv::Vec2b a(60, 200), b(200, 60);
  const Picture lr = picture(16, 8, [&](int x, int) { return x < 4 ? a : b; });
  const cv::Mat by_eye = to_rgb_by_eye(lr, {StereoMode::LeftRight, 360}, PixelFormat::Rgb8);
  EXPECT_TRUE(uniform(by_eye.colRange(0, 8)));
  EXPECT_TRUE(uniform(by_eye.colRange(8, 16)));
  EXPECT_NE(by_eye.at<cv::Vec3b>(0, 0), by_eye.at<cv::Vec3b>(0, 8));
  const cv::Mat whole = to_rgb(lr, PixelFormat::Rgb8);
  EXPECT_NE(whole.at<cv::Vec3b>(0, 7), whole.at<cv::Vec3b>(0, 0));  // the mix it prevents

  const Picture tb = picture(8, 16, [&](int, int y) { return y < 4 ? a : b; });
  const cv::Mat rows = to_rgb_by_eye(tb, {StereoMode::TopBottom, 360}, PixelFormat::Rgb8);
  EXPECT_TRUE(uniform(rows.rowRange(0, 8)));
  EXPECT_TRUE(uniform(rows.rowRange(8, 16)));
  EXPECT_NE(to_rgb(tb, PixelFormat::Rgb8).at<cv::Vec3b>(7, 0), rows.at<cv::Vec3b>(0, 0));
}

// Within a 360 eye the chroma wraps at the eye's own seam; a VR180 image's edges are clamped
// (its columns are half a turn apart), mono or stereo.
TEST(EyePicture, ColumnsWrapInA360ImageAndClampInAVr180One) {
  const cv::Vec2b edge(60, 200), inside(200, 60);
  // Each 8-column eye: chroma sample 0 differs from the rest.
  const Picture p = picture(16, 4, [&](int x, int) { return x % 4 == 0 ? edge : inside; });
  const cv::Mat wrap = to_rgb_by_eye(p, {StereoMode::LeftRight, 360}, PixelFormat::Rgb8);
  const cv::Mat clamp = to_rgb_by_eye(p, {StereoMode::LeftRight, 180}, PixelFormat::Rgb8);
  for (const int last : {7, 15}) {
    EXPECT_NE(wrap.at<cv::Vec3b>(0, last), wrap.at<cv::Vec3b>(0, last - 2));  // half of `edge`
    EXPECT_EQ(clamp.at<cv::Vec3b>(0, last), clamp.at<cv::Vec3b>(0, last - 2));
  }
  const Picture mono = picture(8, 4, [&](int x, int) { return x == 0 ? edge : inside; });
  const cv::Mat m = to_rgb_by_eye(mono, {StereoMode::Mono, 180}, PixelFormat::Rgb8);
  EXPECT_EQ(m.at<cv::Vec3b>(0, 7), m.at<cv::Vec3b>(0, 5));
  EXPECT_EQ(to_rgb_by_eye(mono, {}, PixelFormat::Rgb8).at<cv::Vec3b>(0, 7),
            to_rgb(mono, PixelFormat::Rgb8).at<cv::Vec3b>(0, 7));
}

// A half off the chroma grid (an odd half height in 4:2:0) is converted as one frame, as the GL
// layer then converts it; cut_picture refuses it and cuts an aligned half's chroma at half size.
TEST(EyePicture, AHalfOffTheChromaGridIsConvertedAsOneFrame) {
  const Picture p = picture(8, 10, [](int x, int y) {
    return cv::Vec2b(static_cast<uchar>(40 * x), static_cast<uchar>(30 * y));
  });
  const cv::Mat by_eye = to_rgb_by_eye(p, {StereoMode::TopBottom, 360}, PixelFormat::RgbF32);
  const cv::Mat whole = to_rgb(p, PixelFormat::RgbF32);
  EXPECT_EQ(cv::norm(by_eye, whole, cv::NORM_INF), 0.0);
  Picture half;
  EXPECT_FALSE(cut_picture(p, {0, 5, 8, 5}, half));
  ASSERT_TRUE(cut_picture(p, {4, 2, 4, 8}, half));
  EXPECT_EQ(half.planes[0].size(), cv::Size(4, 8));
  EXPECT_EQ(half.planes[1].size(), cv::Size(2, 4));
  EXPECT_EQ(half.planes[2].at<uchar>(0, 0), p.planes[2].at<uchar>(1, 2));
}

// The encoder's side: each eye's half encoded on its own, so the chroma samples next to the
// boundary carry only their own eye's colour (as one frame they average both sides).
TEST(EyePicture, EachEyeIsEncodedFromItsOwnHalf) {
  cv::Mat rgb(8, 16, CV_32FC3, cv::Scalar(0.9f, 0.1f, 0.1f));
  rgb.colRange(8, 16).setTo(cv::Scalar(0.1f, 0.1f, 0.9f));
  YcbcrInfo info;  // 4:2:0, left-sited, limited range
  const Picture by_eye = rgb_to_ycbcr_by_eye(rgb, info, {StereoMode::LeftRight, 360});
  const Picture whole = rgb_to_ycbcr(rgb, info);
  for (int plane = 1; plane < 3; ++plane) {
    const cv::Mat& c = by_eye.planes[static_cast<std::size_t>(plane)];
    // Chroma sample 4 sits on luma column 8, the right eye's first: its tent reaches column 7.
    EXPECT_EQ(c.at<uchar>(0, 4), c.at<uchar>(0, 7)) << plane;
    EXPECT_EQ(c.at<uchar>(0, 3), c.at<uchar>(0, 0)) << plane;
    EXPECT_NE(whole.planes[static_cast<std::size_t>(plane)].at<uchar>(0, 4), c.at<uchar>(0, 4));
  }
  // Decoded eye by eye, each half is its own colour again.
  const cv::Mat back = to_rgb_by_eye(by_eye, {StereoMode::LeftRight, 360}, PixelFormat::Rgb8);
  EXPECT_TRUE(uniform(back.colRange(0, 8)));
  EXPECT_TRUE(uniform(back.colRange(8, 16)));
  // Mono: the whole-frame encoder, byte for byte.
  const Picture mono = rgb_to_ycbcr_by_eye(rgb, info, {});
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(cv::norm(mono.planes[i], whole.planes[i], cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace vdfx::io
