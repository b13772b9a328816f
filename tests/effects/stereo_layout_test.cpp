/// @file
/// @brief StereoLayout (names, the frame's split, the shape hint, the coverage weight) and the
/// sampler on one eye's image: VR180 coverage, clamped columns, no read across the halves.
#include "effects/stereo_layout.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <tuple>

#include "effects/coords.h"
#include "effects/equirect_sampler.h"

namespace vdfx::effects {
namespace {

TEST(StereoLayout, NamesRoundTrip) {
  for (StereoMode m :
       {StereoMode::Mono, StereoMode::TopBottom, StereoMode::LeftRight, StereoMode::RightLeft})
    EXPECT_EQ(stereo_mode_from_name(stereo_mode_name(m)), m);
  EXPECT_FALSE(stereo_mode_from_name("side-by-side"));
  EXPECT_FALSE(stereo_mode_from_name("Mono"));
}

TEST(StereoLayout, EyeRectangles) {
  const struct {
    StereoMode mode;
    PixelRect left, right;
  } rows[] = {
      {StereoMode::Mono, {0, 0, 64, 32}, {0, 0, 64, 32}},
      {StereoMode::TopBottom, {0, 0, 64, 16}, {0, 16, 64, 16}},
      {StereoMode::LeftRight, {0, 0, 32, 32}, {32, 0, 32, 32}},
      {StereoMode::RightLeft, {32, 0, 32, 32}, {0, 0, 32, 32}},
  };
  for (const auto& row : rows) {
    SCOPED_TRACE(std::string(stereo_mode_name(row.mode)));
    const StereoLayout l{row.mode, 360};
    EXPECT_EQ(eye_rect(l, EyeIndex::Left, 64, 32), row.left);
    EXPECT_EQ(eye_rect(l, EyeIndex::Right, 64, 32), row.right);
  }
}

TEST(StereoLayout, ALayoutMustDivideTheFrame) {
  EXPECT_FALSE(layout_problem({StereoMode::Mono, 360}, 63, 31));
  EXPECT_FALSE(layout_problem({StereoMode::TopBottom, 360}, 63, 32));
  ASSERT_TRUE(layout_problem({StereoMode::TopBottom, 360}, 64, 31));
  EXPECT_NE(layout_problem({StereoMode::TopBottom, 360}, 64, 31)->find("even frame height"),
            std::string::npos);
  EXPECT_TRUE(layout_problem({StereoMode::LeftRight, 360}, 63, 32));
  EXPECT_TRUE(layout_problem({StereoMode::RightLeft, 180}, 1, 32));
  EXPECT_TRUE(layout_problem({StereoMode::Mono, 0}, 64, 32));
  EXPECT_TRUE(layout_problem({StereoMode::Mono, 270}, 64, 32));
}

TEST(StereoLayout, HintForStereoShapedFrames) {
  EXPECT_NE(stereo_shape_hint(2048, 2048).find("--layout"), std::string::npos);
  EXPECT_NE(stereo_shape_hint(4096, 1024).find("--layout"), std::string::npos);
  EXPECT_EQ(stereo_shape_hint(4096, 2048), "");
  EXPECT_EQ(stereo_shape_hint(0, 0), "");
}

TEST(StereoLayout, CoverageWeight) {
  const StereoLayout vr180{StereoMode::LeftRight, 180};
  EXPECT_EQ(coverage_weight({StereoMode::Mono, 360}, 179.0), 1.0);
  EXPECT_EQ(coverage_weight(vr180, 0.0), 1.0);
  EXPECT_EQ(coverage_weight(vr180, 90.0 - kCoverageEdgeDeg), 1.0);
  EXPECT_DOUBLE_EQ(coverage_weight(vr180, 89.0), 0.5);
  EXPECT_DOUBLE_EQ(coverage_weight(vr180, -89.0), 0.5);
  EXPECT_EQ(coverage_weight(vr180, 90.0), 0.0);
  EXPECT_EQ(coverage_weight(vr180, 135.0), 0.0);
}

/// A frame whose left and right halves are each a constant colour.
cv::Mat two_halves(int w, int h, cv::Vec3f left, cv::Vec3f right) {
  cv::Mat m(h, w, CV_32FC3);
  m.colRange(0, w / 2).setTo(cv::Scalar(left[0], left[1], left[2]));
  m.colRange(w / 2, w).setTo(cv::Scalar(right[0], right[1], right[2]));
  return m;
}

TEST(StereoSampler, EachEyeReadsOnlyItsHalfAtEveryLevel) {
  // Side by side: the left eye red, the right eye blue. Bilinear taps at the seam and every
  // mip level of an eye's image hold only its own colour.
  const cv::Mat frame = two_halves(128, 32, {1, 0, 0}, {0, 0, 1});
  const StereoLayout l{StereoMode::LeftRight, 360};
  for (EyeIndex eye : {EyeIndex::Left, EyeIndex::Right}) {
    const EquirectSampler s(eye_image(frame, l, eye));
    const double want_r = eye == EyeIndex::Left ? 1.0 : 0.0;
    for (int l = 0; l < s.levels(); ++l)
      for (double u : {0.0, 0.001, 0.5, 0.999})
        EXPECT_DOUBLE_EQ(s.sample_uv(u, 0.5, l).x(), want_r);
  }
}

TEST(StereoSampler, Vr180MapsAHalfTurnAndIsBlackOutside) {
  // A 180 image whose columns hold their own azimuth: column centre i + 0.5 of w spans -90..90.
  const int w = 90, h = 45;
  cv::Mat img(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float az = static_cast<float>(-90.0 + 180.0 * (x + 0.5) / w);
      img.at<cv::Vec3f>(y, x) = cv::Vec3f(az / 90.0f, 1.0f, 0.0f);
    }
  SamplerOptions o;
  o.filter = SampleFilter::Bilinear;
  o.coverage_deg = 180;
  const EquirectSampler s(img, o);
  for (double az : {-80.0, -30.0, 0.0, 12.5, 60.0, 87.0}) {
    const Eigen::Vector3d c = s.sample(to_unit({az, 10.0}));
    EXPECT_NEAR(c.x(), az / 90.0, 1e-6) << az;
    EXPECT_NEAR(c.y(), 1.0, 1e-12) << az;
  }
  EXPECT_NEAR(s.sample(to_unit({89.0, 0.0})).y(), 0.5, 1e-9);  // inside the 2-degree fade
  for (double az : {90.0, 91.0, 120.0, 180.0, -100.0, -179.0})
    EXPECT_EQ(s.sample(to_unit({az, 0.0})), Eigen::Vector3d::Zero()) << az;
  // Columns are clamped at the edge, never wrapped onto the other edge.
  EXPECT_NEAR(s.sample_uv(0.999, 0.5).x(), img.at<cv::Vec3f>(0, w - 1)[0], 1e-6);
  EXPECT_NEAR(s.sample_uv(0.001, 0.5).x(), img.at<cv::Vec3f>(0, 0)[0], 1e-6);
}

TEST(StereoSampler, Vr180FootprintCountsTwiceTheTexelsPerDegree) {
  // A VR180 image of width w has as many texels per degree as a 360 image of width 2 w holding
  // it in its middle half: the footprint filter must take the same taps at the same levels in
  // both (views whose footprints stay inside the half and need levels 0..2).
  cv::Mat half_img(64, 256, CV_32FC3);
  cv::theRNG().state = 21;
  cv::randu(half_img, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  cv::Mat full_img(64, 512, CV_32FC3, cv::Scalar::all(0.25));
  half_img.copyTo(full_img.colRange(128, 384));
  SamplerOptions o;
  o.coverage_deg = 180;
  const EquirectSampler half(half_img, o), full(full_img);
  for (const auto& [az, alt, fov] : {std::tuple{0.0, 0.0, 100.0}, {-30.0, 20.0, 50.0}}) {
    const ViewCamera cam = ViewCamera::from_horizontal_fov({{az, alt}, 10.0}, fov, 40, 30);
    for (const auto& [x, y] : {std::pair{20.5, 15.5}, {3.5, 27.5}, {36.5, 2.5}}) {
      const Eigen::Vector3d a = half.sample_pixel(cam, x, y), b = full.sample_pixel(cam, x, y);
      EXPECT_LT((a - b).norm(), 1e-6) << az << " " << x << "," << y;
    }
  }
}

}  // namespace
}  // namespace vdfx::effects
