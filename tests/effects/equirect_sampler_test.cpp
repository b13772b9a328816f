/// @file
/// @brief EquirectSampler: bilinear exactness, seam continuity, poles, area-aware filtering.
#include "effects/equirect_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "effects/coords.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"

namespace vdfx::effects {
namespace {

cv::Mat random_equirect(int w, int h, unsigned seed) {
  cv::Mat img(h, w, CV_32FC3);
  cv::theRNG().state = seed;
  cv::randu(img, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  return img;
}

TEST(EquirectSampler, BilinearIsExactOnALinearRamp) {
  // value = a + b x + c y in texel coordinates (texel centres at integer x, y).
  const int w = 64, h = 32;
  cv::Mat ramp(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      ramp.at<cv::Vec3f>(y, x) = cv::Vec3f(0.01f * x, 0.02f * y, 0.5f + 0.003f * x - 0.004f * y);
  const EquirectSampler s(ramp, {SampleFilter::Bilinear, PoleRows::Clamp});
  for (double u = 0.02; u < 0.98; u += 0.0371) {
    for (double v = 0.03; v < 0.97; v += 0.0413) {
      const double x = u * w - 0.5, y = v * h - 0.5;
      const Eigen::Vector3d got = s.sample_uv(u, v);
      EXPECT_NEAR(got.x(), 0.01 * x, 1e-6);
      EXPECT_NEAR(got.y(), 0.02 * y, 1e-6);
      EXPECT_NEAR(got.z(), 0.5 + 0.003 * x - 0.004 * y, 1e-6);
      // Through a direction: the contract's u = 0.5 + az/360, v = 0.5 - alt/180.
      const Eigen::Vector3d via = s.sample(to_unit(from_equirect_uv({u, v})));
      EXPECT_LT((via - got).norm(), 1e-5);
    }
  }
}

TEST(EquirectSampler, SeamBlendsLastAndFirstColumn) {
  const cv::Mat img = random_equirect(48, 24, 3);
  const EquirectSampler s(img, {SampleFilter::Bilinear, PoleRows::Clamp});
  const int row = 10;
  const double v = (row + 0.5) / 24.0;
  const cv::Vec3f first = img.at<cv::Vec3f>(row, 0), last = img.at<cv::Vec3f>(row, 47);
  // Azimuth 180 (u = 1) and -180 (u = 0) are the same place: halfway between the two columns.
  for (double u : {0.0, 1.0}) {
    const Eigen::Vector3d got = s.sample_uv(u, v);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], 0.5 * (first[k] + last[k]), 1e-6);
  }
  // Sweeping across the seam in fine steps changes the value no faster than bilinear allows.
  Eigen::Vector3d prev = s.sample(to_unit({170.0, 0.0 + 90.0 - v * 180.0}));
  double worst = 0.0;
  for (double az = 170.0; az <= 190.0; az += 0.05) {
    const Eigen::Vector3d cur = s.sample(to_unit({wrap_azimuth_deg(az), 90.0 - v * 180.0}));
    worst = std::max(worst, (cur - prev).cwiseAbs().maxCoeff());
    prev = cur;
  }
  const double step_texels = 0.05 / 360.0 * 48;  // each step moves this far; values are in [0, 1]
  EXPECT_LE(worst, step_texels + 1e-6);
}

TEST(EquirectSampler, PolesGiveFiniteValuesAndRespectTheirRow) {
  cv::Mat img = random_equirect(64, 32, 5);
  img.row(0).setTo(cv::Scalar(0.2, 0.4, 0.6));
  img.row(31).setTo(cv::Scalar(0.9, 0.1, 0.3));
  for (PoleRows rows : {PoleRows::Clamp, PoleRows::AcrossPole}) {
    for (SampleFilter filter : {SampleFilter::Bilinear, SampleFilter::AreaAware}) {
      const EquirectSampler s(img, {filter, rows});
      const Eigen::Vector3d north = s.sample(Eigen::Vector3d(0, 1, 0));
      const Eigen::Vector3d south = s.sample(Eigen::Vector3d(0, -1, 0));
      EXPECT_LT((north - Eigen::Vector3d(0.2, 0.4, 0.6)).norm(), 1e-6);
      EXPECT_LT((south - Eigen::Vector3d(0.9, 0.1, 0.3)).norm(), 1e-6);
      for (double az = -180.0; az <= 180.0; az += 7.5) {
        for (double alt : {89.9999, 90.0, -89.9999, -90.0}) {
          const Eigen::Vector3d dir = to_unit({az, alt});
          const Footprint huge{1e9, 1e9};
          EXPECT_TRUE(s.sample(dir).allFinite());
          EXPECT_TRUE(s.sample(dir, huge).allFinite());
        }
      }
    }
  }
}

TEST(EquirectSampler, AcrossPoleIsContinuousOverThePole) {
  const cv::Mat img = random_equirect(64, 32, 9);
  const EquirectSampler across(img, {SampleFilter::Bilinear, PoleRows::AcrossPole});
  const EquirectSampler clamp(img, {SampleFilter::Bilinear, PoleRows::Clamp});
  double worst_across = 0.0, worst_clamp = 0.0;
  for (double az = -180.0; az < 0.0; az += 11.0) {
    // Two points a hair's breadth either side of the north pole, on opposite meridians.
    const Eigen::Vector3d a = to_unit({az, 89.999}), b = to_unit({az + 180.0, 89.999});
    worst_across = std::max(worst_across, (across.sample(a) - across.sample(b)).norm());
    worst_clamp = std::max(worst_clamp, (clamp.sample(a) - clamp.sample(b)).norm());
  }
  EXPECT_LT(worst_across, 1e-3);
  EXPECT_GT(worst_clamp, 0.1);  // the clamped rows are not continuous over the pole
}

TEST(EquirectSampler, RipmapLevelsAverage) {
  const cv::Mat img = random_equirect(64, 32, 11);
  const EquirectSampler s(img, {SampleFilter::AreaAware, PoleRows::Clamp});
  EXPECT_EQ(s.max_level_x(), 6);
  EXPECT_EQ(s.max_level_y(), 5);
  // The coarsest horizontal level of row-level 0 is one column: each row's mean.
  for (int row : {0, 7, 31}) {
    const cv::Scalar mean = cv::mean(img.row(row));
    const Eigen::Vector3d got = s.sample_uv(0.3, (row + 0.5) / 32.0, 6, 0);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], mean[k], 1e-5) << row;
  }
  // A footprint of at most one texel is level 0, exactly bilinear.
  const Eigen::Vector3d dir = to_unit({12.3, -4.5});
  EXPECT_EQ(s.sample(dir, {0.8, 1.0}), s.sample(dir));
}

TEST(EquirectSampler, FootprintFollowsTheRowLength) {
  const EquirectSampler s(random_equirect(360, 180, 1), {SampleFilter::AreaAware, PoleRows::Clamp});
  // One degree steps: one texel on the equator; 1 / cos(alt) texels horizontally elsewhere.
  for (double alt : {0.0, 60.0, 84.0}) {
    const Eigen::Vector3d d = to_unit({10, alt});
    const Footprint f = s.footprint(d, to_unit({11, alt}), to_unit({10, alt - 1.0}));
    EXPECT_NEAR(f.du_texels, 1.0, 1e-9);
    EXPECT_NEAR(f.dv_texels, 1.0, 1e-9);
    const Eigen::Vector3d right = to_unit({10.0 + 1.0 / std::cos(alt * kDegToRad), alt});
    EXPECT_NEAR(s.footprint(d, right, d).du_texels, 1.0 / std::cos(alt * kDegToRad), 1e-9);
  }
  // Across the seam the short way round.
  EXPECT_NEAR(s.footprint(to_unit({179.5, 0}), to_unit({-179.5, 0}), to_unit({179.5, 0})).du_texels,
              1.0, 1e-9);
}

TEST(EquirectSampler, AreaAwareDoesNotAliasAtThePole) {
  // One-texel stripes of 0 and 1 in azimuth: looking straight up, a view pixel covers many
  // stripes; the area-aware filter sees their mean, plain bilinear picks stripes (aliasing).
  cv::Mat stripes(256, 512, CV_32FC3);
  for (int x = 0; x < 512; ++x) stripes.col(x).setTo(cv::Scalar::all(x % 2));
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 80}, 0}, 60.0, 64, 64);
  const auto spread = [&](SampleFilter f) {
    const EquirectSampler s(stripes, {f, PoleRows::Clamp});
    const cv::Mat view = sample_view(s, cam);
    cv::Scalar mean, dev;
    cv::meanStdDev(view.reshape(1), mean, dev);
    return std::pair{mean[0], dev[0]};
  };
  const auto [area_mean, area_dev] = spread(SampleFilter::AreaAware);
  const auto [bilinear_mean, bilinear_dev] = spread(SampleFilter::Bilinear);
  EXPECT_NEAR(area_mean, 0.5, 0.02);
  EXPECT_LT(area_dev, 0.05);
  EXPECT_GT(bilinear_dev, 0.2);
  (void)bilinear_mean;
}

TEST(EquirectSampler, RejectsWrongType) {
  EXPECT_THROW(EquirectSampler(cv::Mat(4, 8, CV_8UC3)), std::invalid_argument);
  // Braces: clang reads EquirectSampler(cv::Mat()) as a declaration (the sanitizer CI builds with
  // it).
  EXPECT_THROW(EquirectSampler{cv::Mat()}, std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
