/// @file
/// @brief EquirectSampler: bilinear exactness, seam continuity, poles, the mip chain's levels,
/// the footprint filter's pixel.
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
    for (SampleFilter filter : {SampleFilter::Bilinear, SampleFilter::Footprint}) {
      const EquirectSampler s(img, {filter, rows});
      const Eigen::Vector3d north = s.sample(Eigen::Vector3d(0, 1, 0));
      const Eigen::Vector3d south = s.sample(Eigen::Vector3d(0, -1, 0));
      EXPECT_LT((north - Eigen::Vector3d(0.2, 0.4, 0.6)).norm(), 1e-6);
      EXPECT_LT((south - Eigen::Vector3d(0.9, 0.1, 0.3)).norm(), 1e-6);
      for (double az = -180.0; az <= 180.0; az += 7.5) {
        for (double alt : {89.9999, 90.0, -89.9999, -90.0}) {
          const Eigen::Vector3d dir = to_unit({az, alt});
          EXPECT_TRUE(s.sample(dir).allFinite());
          EXPECT_TRUE(s.sample_lod(0.3, 0.0, 1e9).allFinite());
        }
      }
      // A pixel centred exactly on each pole, looking straight at it (the Jacobian's worst case).
      for (double alt : {90.0, -90.0}) {
        const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, alt}, 0}, 90.0, 9, 9);
        EXPECT_TRUE(s.sample_pixel(cam, 4.5, 4.5).allFinite()) << alt;
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

TEST(EquirectSampler, MipLevelsAreAreaAverages) {
  const cv::Mat img = random_equirect(64, 32, 11);
  const EquirectSampler s(img, {SampleFilter::Footprint, PoleRows::Clamp});
  EXPECT_EQ(s.levels(), 7);  // 64x32 .. 1x1, GL's count
  // Level 6 is one texel: the image's mean, wherever it is read.
  const cv::Scalar mean = cv::mean(img);
  for (const auto& [u, v] : {std::pair{0.3, 0.5}, {0.9, 0.01}}) {
    const Eigen::Vector3d got = s.sample_uv(u, v, 6);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], mean[k], 1e-5);
  }
  // Level 1 at a texel centre: the 2 x 2 block's mean.
  const Eigen::Vector3d got = s.sample_uv((5 + 0.5) / 32.0, (3 + 0.5) / 16.0, 1);
  cv::Scalar block = cv::mean(img(cv::Rect(10, 6, 2, 2)));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], block[k], 1e-6);
  // Trilinear halfway between two levels is their mean; lod <= 0 is level 0.
  const Eigen::Vector3d half = s.sample_lod(0.41, 0.37, 2.5);
  EXPECT_LT((half - 0.5 * (s.sample_uv(0.41, 0.37, 2) + s.sample_uv(0.41, 0.37, 3))).norm(), 1e-12);
  EXPECT_EQ(s.sample_lod(0.41, 0.37, -3.0), s.sample_uv(0.41, 0.37, 0));
}

TEST(EquirectSampler, FootprintIsBilinearWhereTheViewEnlargesTheImage) {
  // 360x180 texels, a 30 degree view 300 pixels wide: 10 pixels per texel at the centre.
  const cv::Mat img = random_equirect(360, 180, 13);
  const EquirectSampler foot(img), bilinear(img, {SampleFilter::Bilinear, PoleRows::Clamp});
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{20, 10}, 5}, 30.0, 300, 200);
  for (const auto& [x, y] : {std::pair{150.5, 100.5}, {3.5, 7.5}, {290.5, 190.5}}) {
    const Eigen::Vector3d a = foot.sample_pixel(cam, x, y), b = bilinear.sample_pixel(cam, x, y);
    EXPECT_LT((a - b).norm(), 1e-12) << x << "," << y;
  }
}

TEST(EquirectSampler, FootprintDoesNotAliasAtThePole) {
  // One-texel stripes of 0 and 1 in azimuth: looking up, a view pixel covers many stripes; the
  // footprint filter sees their mean, plain bilinear picks stripes (aliasing).
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
  const auto [foot_mean, foot_dev] = spread(SampleFilter::Footprint);
  const auto [bilinear_mean, bilinear_dev] = spread(SampleFilter::Bilinear);
  EXPECT_NEAR(foot_mean, 0.5, 0.02);
  EXPECT_LT(foot_dev, 0.05);
  EXPECT_GT(bilinear_dev, 0.2);
  (void)bilinear_mean;
}

TEST(EquirectSampler, FootprintDoesNotBlurAcrossRowsNearThePole) {
  // Bands of 4 rows, seen near the pole: a pixel covers about 1.3 rows and up to tens of
  // columns. One isotropic level as coarse as the long axis (max_anisotropy 1, GL's choice)
  // averages the bands to grey; taps along the long axis at the short axis' level keep them.
  cv::Mat rows(256, 512, CV_32FC3);
  for (int y = 0; y < 256; ++y) rows.row(y).setTo(cv::Scalar::all((y / 4) % 2));
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 75}, 0}, 60.0, 64, 64);
  const EquirectSampler point(rows, {SampleFilter::Bilinear, PoleRows::Clamp});
  cv::Mat truth(64, 64, CV_32FC3);  // 8 x 8 point samples per pixel
  truth.forEach<cv::Vec3f>([&](cv::Vec3f& px, const int* pos) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int b = 0; b < 8; ++b)
      for (int a = 0; a < 8; ++a)
        sum += point.sample(cam.ray(pos[1] + (a + 0.5) / 8, pos[0] + (b + 0.5) / 8));
    px = cv::Vec3f::all(static_cast<float>(sum.x() / 64));
  });
  const auto rms = [&](double max_anisotropy) {
    SamplerOptions o;
    o.max_anisotropy = max_anisotropy;
    const cv::Mat d = sample_view(EquirectSampler(rows, o), cam) - truth;
    const cv::Mat sq = d.mul(d);
    return std::sqrt(cv::mean(sq.reshape(1))[0]);
  };
  const double footprint = rms(kDefaultMaxAnisotropy), isotropic = rms(1.0);
  EXPECT_LT(footprint, 0.5 * isotropic) << footprint << " vs " << isotropic;
}

TEST(EquirectSampler, RejectsWrongType) {
  EXPECT_THROW(EquirectSampler(cv::Mat(4, 8, CV_8UC3)), std::invalid_argument);
  // Braces: clang reads EquirectSampler(cv::Mat()) as a declaration (the sanitizer CI builds with
  // it).
  EXPECT_THROW(EquirectSampler{cv::Mat()}, std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
