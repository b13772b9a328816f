/// @file
/// @brief Still images: depth scaling, channel order, tone mapping of radiance, clear errors.
#include "io/image_source.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/input_error.h"
#include "io/tone_map.h"
#include "io_test_util.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;

using testing::temp_dir;

TEST(ImageSource, Png8BitIsScaledAsStoredInRgbOrder) {
  const auto dir = temp_dir("img_png8");
  cv::Mat bgr(2, 3, CV_8UC3, cv::Scalar(0, 0, 0));
  bgr.at<cv::Vec3b>(0, 0) = {10, 20, 255};  // B G R
  bgr.at<cv::Vec3b>(1, 2) = {255, 128, 0};
  ASSERT_TRUE(cv::imwrite((dir / "a.png").string(), bgr));
  const LoadedImage img = load_image(dir / "a.png");
  ASSERT_EQ(img.rgb.type(), CV_32FC3);
  EXPECT_FALSE(img.tone_mapped);
  EXPECT_EQ(img.source_depth, CV_8U);
  EXPECT_EQ(img.rgb.size(), cv::Size(3, 2));
  EXPECT_FLOAT_EQ(img.rgb.at<cv::Vec3f>(0, 0)[0], 1.0f);
  EXPECT_FLOAT_EQ(img.rgb.at<cv::Vec3f>(0, 0)[1], 20.0f / 255.0f);
  EXPECT_FLOAT_EQ(img.rgb.at<cv::Vec3f>(0, 0)[2], 10.0f / 255.0f);
  EXPECT_FLOAT_EQ(img.rgb.at<cv::Vec3f>(1, 2)[0], 0.0f);
  EXPECT_FLOAT_EQ(img.rgb.at<cv::Vec3f>(1, 2)[1], 128.0f / 255.0f);
  EXPECT_FLOAT_EQ(img.rgb.at<cv::Vec3f>(1, 2)[2], 1.0f);
}

TEST(ImageSource, Png16BitGreyAndAlpha) {
  const auto dir = temp_dir("img_png16");
  cv::Mat grey(1, 2, CV_16UC1);
  grey.at<std::uint16_t>(0, 0) = 65535;
  grey.at<std::uint16_t>(0, 1) = 32768;
  ASSERT_TRUE(cv::imwrite((dir / "g.png").string(), grey));
  const LoadedImage g = load_image(dir / "g.png");
  EXPECT_EQ(g.source_depth, CV_16U);
  EXPECT_FLOAT_EQ(g.rgb.at<cv::Vec3f>(0, 0)[1], 1.0f);
  for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(g.rgb.at<cv::Vec3f>(0, 1)[k], 32768.0f / 65535.0f);

  cv::Mat bgra(1, 1, CV_8UC4, cv::Scalar(51, 102, 204, 0));  // fully transparent: alpha dropped
  ASSERT_TRUE(cv::imwrite((dir / "a.png").string(), bgra));
  const LoadedImage a = load_image(dir / "a.png");
  EXPECT_FLOAT_EQ(a.rgb.at<cv::Vec3f>(0, 0)[0], 0.8f);
  EXPECT_FLOAT_EQ(a.rgb.at<cv::Vec3f>(0, 0)[2], 0.2f);
}

TEST(ImageSource, JpegLoadsCloseToStored) {
  const auto dir = temp_dir("img_jpeg");
  cv::Mat bgr(16, 16, CV_8UC3, cv::Scalar(40, 120, 200));
  ASSERT_TRUE(cv::imwrite((dir / "a.jpg").string(), bgr, {cv::IMWRITE_JPEG_QUALITY, 100}));
  const LoadedImage img = load_image(dir / "a.jpg");
  EXPECT_NEAR(img.rgb.at<cv::Vec3f>(8, 8)[0], 200.0 / 255.0, 3.0 / 255.0);
  EXPECT_NEAR(img.rgb.at<cv::Vec3f>(8, 8)[2], 40.0 / 255.0, 3.0 / 255.0);
}

/// The documented operator, written out for one colour with the image's log-average luminance.
cv::Vec3f reinhard_expected(cv::Vec3f c, double l_avg, double key = 0.18) {
  const double lw = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  const double l = key / l_avg * lw;
  const double ratio = l / (1.0 + l) / lw;
  cv::Vec3f out;
  for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(srgb_encode(c[k] * ratio));
  return out;
}

TEST(ToneMap, MatchesReinhardGlobalOperator) {
  cv::Mat lin(1, 2, CV_32FC3);
  lin.at<cv::Vec3f>(0, 0) = {4.0f, 2.0f, 1.0f};
  lin.at<cv::Vec3f>(0, 1) = {0.05f, 0.1f, 0.2f};
  const auto lum = [](cv::Vec3f c) {
    return 0.2126 * double(c[0]) + 0.7152 * double(c[1]) + 0.0722 * double(c[2]);
  };
  const double l0 = lum(lin.at<cv::Vec3f>(0, 0)), l1 = lum(lin.at<cv::Vec3f>(0, 1));
  const double l_avg = std::exp(0.5 * (std::log(1e-6 + l0) + std::log(1e-6 + l1)));
  EXPECT_NEAR(log_average_luminance(lin), l_avg, 1e-12 * l_avg);
  const cv::Mat out = tone_map_reinhard(lin);
  for (int x = 0; x < 2; ++x) {
    const cv::Vec3f e = reinhard_expected(lin.at<cv::Vec3f>(0, x), l_avg);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(out.at<cv::Vec3f>(0, x)[k], e[k], 1e-6) << x << "," << k;
  }
}

TEST(ToneMap, ExposureNormalisationMakesOutputScaleInvariant) {
  cv::Mat lin(4, 4, CV_32FC3);
  cv::randu(lin, 0.01f, 5.0f);
  const cv::Mat a = tone_map_reinhard(lin);
  const cv::Mat b = tone_map_reinhard(lin * 1000.0f);
  EXPECT_LT(cv::norm(a, b, cv::NORM_INF), 1e-4);
  double lo = 0, hi = 0;
  cv::minMaxLoc(a.reshape(1), &lo, &hi);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
}

TEST(ToneMap, SrgbEncodeKnownPoints) {
  EXPECT_DOUBLE_EQ(srgb_encode(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgb_encode(1.0), 1.0);
  EXPECT_DOUBLE_EQ(srgb_encode(0.002), 12.92 * 0.002);  // linear segment
  EXPECT_NEAR(srgb_encode(0.18), 0.4613561, 1e-6);      // middle grey
  EXPECT_DOUBLE_EQ(srgb_encode(7.0), 1.0);              // clamped
}

TEST(ToneMap, NegativeAndNonFiniteSamplesAreBlack) {
  cv::Mat lin(1, 3, CV_32FC3);
  lin.at<cv::Vec3f>(0, 0) = {-1.0f, -1.0f, -1.0f};
  lin.at<cv::Vec3f>(0, 1) = {std::nanf(""), INFINITY, 0.0f};
  lin.at<cv::Vec3f>(0, 2) = {1.0f, 1.0f, 1.0f};
  const cv::Mat out = tone_map_reinhard(lin);
  EXPECT_EQ(out.at<cv::Vec3f>(0, 0), cv::Vec3f(0, 0, 0));
  EXPECT_EQ(out.at<cv::Vec3f>(0, 1), cv::Vec3f(0, 0, 0));
  EXPECT_GT(out.at<cv::Vec3f>(0, 2)[0], 0.0f);
}

TEST(ImageSource, ExrAndHdrAreToneMapped) {
  const auto dir = temp_dir("img_exr");
  enable_openexr();
  cv::Mat bgr(8, 8, CV_32FC3, cv::Scalar(0.5, 1.0, 2.0));  // linear radiance, B G R
  bgr.at<cv::Vec3f>(0, 0) = {20.0f, 20.0f, 20.0f};
  ASSERT_TRUE(cv::imwrite((dir / "a.exr").string(), bgr));
  ASSERT_TRUE(cv::imwrite((dir / "a.hdr").string(), bgr));
  cv::Mat rgb_lin;
  cv::cvtColor(bgr, rgb_lin, cv::COLOR_BGR2RGB);
  const cv::Mat expected = tone_map_reinhard(rgb_lin);
  const LoadedImage exr = load_image(dir / "a.exr");
  EXPECT_TRUE(exr.tone_mapped);
  EXPECT_EQ(exr.source_depth, CV_32F);
  EXPECT_LT(cv::norm(exr.rgb, expected, cv::NORM_INF), 1e-3);  // EXR may store half floats
  // Red has the most radiance in the file: it must stay the largest channel after mapping.
  EXPECT_GT(exr.rgb.at<cv::Vec3f>(4, 4)[0], exr.rgb.at<cv::Vec3f>(4, 4)[2]);
  const LoadedImage hdr = load_image(dir / "a.hdr");
  EXPECT_TRUE(hdr.tone_mapped);
  EXPECT_LT(cv::norm(hdr.rgb, expected, cv::NORM_INF), 0.02);  // RGBE keeps 8-bit mantissas
}

TEST(ImageSource, BlenderStudioLightExr) {
  // A real equirect radiance map shipped with blender-data (CC0).
  const fs::path p = "/usr/share/blender/datafiles/studiolights/world/forest.exr";
  const LoadedImage img = load_image(p);
  EXPECT_TRUE(img.tone_mapped);
  EXPECT_EQ(img.rgb.cols, 1024);
  EXPECT_EQ(img.rgb.rows, 512);
  double lo = 0, hi = 0;
  cv::minMaxLoc(img.rgb.reshape(1), &lo, &hi);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_TRUE(cv::checkRange(img.rgb));
  // Log-average luminance mapped to key 0.18 lands mid-scale: the picture is neither black nor
  // white on average.
  const cv::Scalar mean = cv::mean(img.rgb);
  EXPECT_GT(mean[1], 0.2);
  EXPECT_LT(mean[1], 0.8);
  EXPECT_GT(hi - lo, 0.5);
}

TEST(ImageSource, ErrorsNameTheFileAndTheReason) {
  const auto dir = temp_dir("img_errors");
  std::ofstream(dir / "junk.png") << "this is not a png";
  const struct {
    fs::path path;
    const char* reason;
  } cases[] = {{dir / "missing.png", "no such file"},
               {dir / "junk.png", "cannot decode"},
               {dir, "is a folder"}};
  for (const auto& c : cases) {
    try {
      load_image(c.path);
      ADD_FAILURE() << c.path << ": no exception";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.path.string()), std::string::npos) << what;
      EXPECT_NE(what.find(c.reason), std::string::npos) << what;
    }
  }
}

TEST(ImageSource, StillImageExtensions) {
  EXPECT_TRUE(is_still_image_path("a/b.PNG"));
  EXPECT_TRUE(is_still_image_path("x.exr"));
  EXPECT_TRUE(is_still_image_path("x.hdr"));
  EXPECT_FALSE(is_still_image_path("x.mp4"));
  EXPECT_FALSE(is_still_image_path("png"));
}

TEST(ImageSource, FramesBeyondTheSizeLimitAreRefusedNamingTheFile) {
  // Issue 11, class 3: a 100000x1 image was taken and failed later with a GL error.
  const auto dir = testing::temp_dir("image_too_large");
  const auto wide = dir / "wide.png";
  cv::imwrite(wide.string(), cv::Mat(1, kMaxFrameSide + 1, CV_8UC3, cv::Scalar(1, 2, 3)));
  try {
    load_image(wide);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(wide.string() + ": the image is 16385x1"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(check_frame_size("f", kMaxFrameSide, kMaxFrameSide / 2));
  EXPECT_THROW(check_frame_size("f", kMaxFrameSide, kMaxFrameSide), InputError);  // 2^28 pixels
  EXPECT_THROW(check_frame_size("f", 1, kMaxFrameSide + 1), InputError);
}

}  // namespace
}  // namespace vdfx::io
