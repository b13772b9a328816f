/// @file
/// @brief The area-average mip chain: GL's level sizes, 2 x 2 means for even sides, exact area
/// weights for odd ones (checked against OpenCV's INTER_AREA, an independent implementation).
#include "effects/mip_chain.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace vdfx::effects {
namespace {

cv::Mat random_image(int w, int h, int channels, unsigned seed) {
  cv::Mat img(h, w, CV_32FC(channels));
  cv::theRNG().state = seed;
  cv::randu(img, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  return img;
}

TEST(MipChain, LevelSizesAreGls) {
  const struct {
    int w, h, levels;
  } cases[] = {{1, 1, 1}, {2, 1, 2}, {64, 32, 7}, {3840, 1920, 12}, {15, 7, 4}, {1, 9, 4}};
  for (const auto& c : cases) {
    EXPECT_EQ(mip_level_count(c.w, c.h), c.levels) << c.w << "x" << c.h;
    const std::vector<cv::Mat> chain = build_mip_chain(random_image(c.w, c.h, 3, 1));
    ASSERT_EQ(static_cast<int>(chain.size()), c.levels);
    int w = c.w, h = c.h;
    for (const cv::Mat& level : chain) {
      EXPECT_EQ(level.cols, w);
      EXPECT_EQ(level.rows, h);
      w = std::max(1, w / 2);
      h = std::max(1, h / 2);
    }
    EXPECT_EQ(chain.back().total(), 1u);
  }
}

TEST(MipChain, EvenSidesAreTwoByTwoMeans) {
  const cv::Mat img = random_image(8, 6, 3, 2);
  const cv::Mat l1 = mip_reduce(img);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      const cv::Scalar m = cv::mean(img(cv::Rect(2 * x, 2 * y, 2, 2)));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(l1.at<cv::Vec3f>(y, x)[k], m[k], 1e-6);
    }
}

TEST(MipChain, OddSidesAreExactAreaAverages) {
  // Odd sides (7 -> 3, 5 -> 2, 15 -> 7, 1 -> 1), one channel and four.
  for (const cv::Size size : {cv::Size(7, 5), cv::Size(15, 9), cv::Size(1, 7), cv::Size(9, 1)}) {
    for (int channels : {1, 4}) {
      const cv::Mat img = random_image(size.width, size.height, channels, 3);
      const cv::Mat ours = mip_reduce(img);
      cv::Mat opencv;
      cv::resize(img, opencv, ours.size(), 0, 0, cv::INTER_AREA);
      EXPECT_LT(cv::norm(ours, opencv, cv::NORM_INF), 1e-5) << size << " x" << channels;
      // Area averages keep the mean where the reduction covers the image exactly.
      const cv::Scalar a = cv::mean(img), b = cv::mean(ours);
      for (int k = 0; k < channels; ++k) EXPECT_NEAR(a[k], b[k], 1e-5);
    }
  }
}

TEST(MipChain, RejectsNonFloatImages) {
  EXPECT_THROW(build_mip_chain(cv::Mat(4, 4, CV_8UC3)), std::invalid_argument);
  EXPECT_THROW(build_mip_chain(cv::Mat()), std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
