/// @file
/// @brief GlTexture's RGBA region upload (the panel textures' path): only the region changes,
/// rows as stored and channels as given, and the full mip chain's level count.
#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

class GlTextureGlTest : public GlTest {};

/// Texel (x, y) of `readback` (read_float: BGRA floats, flipped as for upload()) for the RGBA mat
/// row y of an upload that kept rows as stored, as 8-bit RGBA.
cv::Vec4b texel(const cv::Mat& readback, int x, int y) {
  const cv::Vec4f v = readback.at<cv::Vec4f>(readback.rows - 1 - y, x);
  auto u8 = [](float f) { return static_cast<uchar>(std::lround(f * 255.0f)); };
  return {u8(v[2]), u8(v[1]), u8(v[0]), u8(v[3])};
}

TEST_F(GlTextureGlTest, RgbaRegionUploadChangesOnlyTheRegionWithRowsAsStored) {
  constexpr int kW = 8, kH = 6;
  cv::Mat img(kH, kW, CV_8UC4);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) img.at<cv::Vec4b>(y, x) = cv::Vec4b(10 * x, 20 * y, 7, 255);
  GlTexture t(kW, kH, TexFormat::RGBA8, full_mip_levels(kW, kH));
  t.upload_rgba_region(img, {0, 0, kW, kH});
  cv::Mat back = t.read_float();
  EXPECT_EQ(texel(back, 3, 0), cv::Vec4b(30, 0, 7, 255));  // row 0 stays row 0, R stays R
  EXPECT_EQ(texel(back, 5, 4), cv::Vec4b(50, 80, 7, 255));

  // Paint everything, upload a 3x2 region only: inside it the new values, outside the old.
  img.setTo(cv::Scalar(200, 100, 50, 255));
  const cv::Rect region(2, 1, 3, 2);
  t.upload_rgba_region(img, region);
  back = t.read_float();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const cv::Vec4b want = region.contains({x, y}) ? cv::Vec4b(200, 100, 50, 255)
                                                     : cv::Vec4b(10 * x, 20 * y, 7, 255);
      EXPECT_EQ(texel(back, x, y), want) << x << "," << y;
    }
  EXPECT_THROW(t.upload_rgba_region(img, {6, 0, 3, 1}), GlError);  // beyond the image
  EXPECT_THROW(t.upload_rgba_region(cv::Mat(kH, kW, CV_8UC3), region), GlError);  // not RGBA
}

TEST(GlTexture, FullMipChainGoesDownToOnePixel) {
  EXPECT_EQ(full_mip_levels(1, 1), 1);
  EXPECT_EQ(full_mip_levels(2000, 1200), 11);  // 2000 -> 1000 -> ... -> 1
  EXPECT_EQ(full_mip_levels(1024, 512), 11);
  EXPECT_EQ(full_mip_levels(3, 1025), 11);
}

}  // namespace
}  // namespace vdfx::xr
