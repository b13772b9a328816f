/// @file
/// @brief The colour effects' formulas against hand-computed values, neutral identity, tint luma,
/// vignette geometry, and per-image application against the per-pixel functions.
#include "effects/effect_stack.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <random>

namespace vdfx::effects {
namespace {

using V3 = Eigen::Vector3d;

StackParams with_tint(V3 raw) {
  StackParams p;
  p.set(EffectType::Tint, std::vector<double>{raw.x(), raw.y(), raw.z()});
  return p;
}

// Hand-computed (see the comments): tint (2,1,1) normalises by 0.25*2 + 0.5 + 0.25 = 1.25 to
// (1.6, 0.8, 0.8).
const struct {
  const char* name;
  StackParams params;
  double angle_deg;
  V3 in;
  V3 want;
} kFormulas[] = {
    {"tint", with_tint({2, 1, 1}), 0, {0.2, 0.4, 0.6}, {0.32, 0.32, 0.48}},
    {"exposure +1",
     [] {
       StackParams p;
       p.exposure_stops = 1;
       return p;
     }(),
     0,
     {0.1, 0.2, 0.3},
     {0.2, 0.4, 0.6}},
    {"exposure -2",
     [] {
       StackParams p;
       p.exposure_stops = -2;
       return p;
     }(),
     0,
     {0.1, 0.2, 0.3},
     {0.025, 0.05, 0.075}},
    // Y = 0.25*0.2 + 0.5*0.4 + 0.25*0.8 = 0.45
    {"saturation 2",
     [] {
       StackParams p;
       p.saturation = 2;
       return p;
     }(),
     0,
     {0.2, 0.4, 0.8},
     {-0.05, 0.35, 1.15}},
    {"saturation 0",
     [] {
       StackParams p;
       p.saturation = 0;
       return p;
     }(),
     0,
     {0.2, 0.4, 0.8},
     {0.45, 0.45, 0.45}},
    {"contrast 2",
     [] {
       StackParams p;
       p.contrast = 2;
       return p;
     }(),
     0,
     {0.2, 0.5, 0.9},
     {-0.1, 0.5, 1.3}},
    {"contrast 0.5",
     [] {
       StackParams p;
       p.contrast = 0.5;
       return p;
     }(),
     0,
     {0.2, 0.5, 0.9},
     {0.35, 0.5, 0.7}},
    {"vignette inside R",
     [] {
       StackParams p;
       p.vignette_radius_deg = 10;
       p.vignette_falloff_deg = 10;
       return p;
     }(),
     5,
     {0.4, 0.6, 0.8},
     {0.4, 0.6, 0.8}},
    {"vignette half falloff",
     [] {
       StackParams p;
       p.vignette_radius_deg = 10;
       p.vignette_falloff_deg = 10;
       return p;
     }(),
     15,
     {0.4, 0.6, 0.8},
     {0.2, 0.3, 0.4}},
    {"vignette at R+F",
     [] {
       StackParams p;
       p.vignette_radius_deg = 10;
       p.vignette_falloff_deg = 10;
       return p;
     }(),
     20,
     {0.4, 0.6, 0.8},
     {0, 0, 0}},
    {"vignette beyond",
     [] {
       StackParams p;
       p.vignette_radius_deg = 10;
       p.vignette_falloff_deg = 10;
       return p;
     }(),
     25,
     {0.4, 0.6, 0.8},
     {0, 0, 0}},
    // All five in order: tint -> (0.32, 0.32, 0.48); exposure +1 -> (0.64, 0.64, 0.96);
    // Y = 0.72, saturation 2 -> (0.56, 0.56, 1.2) (above 1: no clamping between effects);
    // contrast 0.5 -> (0.53, 0.53, 0.85); vignette f = 0.5 -> (0.265, 0.265, 0.425).
    {"whole stack in order",
     [] {
       StackParams p = with_tint({2, 1, 1});
       p.exposure_stops = 1;
       p.saturation = 2;
       p.contrast = 0.5;
       p.vignette_radius_deg = 10;
       p.vignette_falloff_deg = 10;
       return p;
     }(),
     15,
     {0.2, 0.4, 0.6},
     {0.265, 0.265, 0.425}},
};

TEST(EffectStack, FormulasMatchHandComputedValues) {
  for (const auto& row : kFormulas) {
    const V3 got = apply_colour_stack(row.in, row.params, row.angle_deg);
    EXPECT_LT((got - row.want).cwiseAbs().maxCoeff(), 1e-12)
        << row.name << ": got " << got.transpose() << ", want " << row.want.transpose();
  }
}

TEST(EffectStack, VignetteFactorEdges) {
  EXPECT_EQ(vignette_factor(0.0, 20.0, 7.0), 1.0);
  EXPECT_EQ(vignette_factor(20.0, 20.0, 7.0), 1.0);
  EXPECT_EQ(vignette_factor(27.0, 20.0, 7.0), 0.0);  // exactly black at R + F
  EXPECT_EQ(vignette_factor(90.0, 20.0, 7.0), 0.0);
  EXPECT_NEAR(vignette_factor(21.75, 20.0, 7.0), 0.75, 1e-15);
  EXPECT_EQ(vignette_factor(20.5, 20.0, 0.0), 0.0);  // hard edge, no division by zero
}

TEST(EffectStack, NeutralEffectsAreExactlyIdentity) {
  const StackParams neutral;
  for (int t = 0; t < kEffectCount; ++t)
    EXPECT_TRUE(neutral.is_neutral(static_cast<EffectType>(t)));
  // Values outside [0, 1] too: the reference must not clamp or round them.
  const V3 odd[] = {{0.1, 0.2, 0.3}, {-0.25, 1.75, 0.333333333333}, {1e-30, 7.0, 0.0}};
  for (const V3& c : odd)
    for (double angle : {0.0, 45.0, 179.9}) EXPECT_EQ(apply_colour_stack(c, neutral, angle), c);

  cv::Mat img(37, 53, CV_32FC3);
  cv::randu(img, cv::Scalar::all(-0.5), cv::Scalar::all(1.5));
  const ViewCamera cam = ViewCamera::from_horizontal_fov({{10, 20}, 5}, 90.0, 53, 37);
  const cv::Mat out = apply_stack(img, neutral, cam);
  EXPECT_EQ(cv::norm(out, img, cv::NORM_INF), 0.0);
}

TEST(EffectStack, TintNeverChangesLuma) {
  // The gain's 0.25/0.5/0.25-weighted mean is 1, so a grey of any level keeps its luma: tint
  // shifts hue, never brightness.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> gain(0.0, 4.0), level(0.0, 1.0);
  const V3 w(kLumaR, kLumaG, kLumaB);
  for (int k = 0; k < 200; ++k) {
    const StackParams p = with_tint({gain(rng), gain(rng), gain(rng)});
    EXPECT_NEAR(w.dot(p.tint_gain), 1.0, 1e-12);
    const double y = level(rng);
    const V3 out = apply_colour_stack(V3::Constant(y), p, 0.0);
    EXPECT_NEAR(w.dot(out), y, 1e-12) << "gain " << p.tint_gain.transpose();
  }
}

TEST(EffectStack, ImageApplicationMatchesThePerPixelFunction) {
  cv::Mat img(24, 40, CV_32FC3);
  cv::randu(img, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  const ViewCamera cam =
      ViewCamera::from_fov_angles({{-30, 10}, 0}, {-0.9, 0.5, 0.7, -0.6}, 40, 24);
  StackParams p = with_tint({1.2, 0.9, 1.4});
  p.exposure_stops = 0.7;
  p.saturation = 1.6;
  p.contrast = 1.3;
  p.vignette_radius_deg = 15;
  p.vignette_falloff_deg = 20;
  const cv::Mat angles = vignette_angle_map(cam);
  const cv::Mat out = apply_stack(img, p, cam);
  for (int j = 0; j < img.rows; ++j) {
    for (int i = 0; i < img.cols; ++i) {
      const cv::Vec3f c = img.at<cv::Vec3f>(j, i);
      const V3 want =
          apply_colour_stack(V3(c[0], c[1], c[2]), p,
                             angle_between(cam.pixel_ray(i, j), cam.optical_axis()) * kRadToDeg);
      const cv::Vec3f got = out.at<cv::Vec3f>(j, i);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-6) << i << "," << j;
      EXPECT_DOUBLE_EQ(angles.at<double>(j, i),
                       angle_between(cam.pixel_ray(i, j), cam.optical_axis()) * kRadToDeg);
    }
  }
}

TEST(EffectStack, VignetteIsCentredOnTheOpticalCentre) {
  // White image, R = 20, F = 10: 1 within 20 degrees of the optical axis, exactly 0 from 30 on.
  const ViewCamera cams[] = {
      ViewCamera::from_horizontal_fov({{0, 0}, 0}, 90.0, 121, 121),
      ViewCamera::from_fov_angles({{50, -20}, 15}, {-0.9, 0.5, 0.7, -0.6}, 140, 120),
  };
  StackParams p;
  p.vignette_radius_deg = 20;
  p.vignette_falloff_deg = 10;
  for (const auto& cam : cams) {
    const cv::Mat white(cam.height(), cam.width(), CV_32FC3, cv::Scalar::all(1.0));
    const cv::Mat out = apply_stack(white, p, cam);
    const cv::Mat angles = vignette_angle_map(cam);
    int inside = 0, outside = 0;
    for (int j = 0; j < out.rows; ++j) {
      for (int i = 0; i < out.cols; ++i) {
        const double d = angles.at<double>(j, i);
        const float v = out.at<cv::Vec3f>(j, i)[1];
        if (d <= 20.0) {
          EXPECT_EQ(v, 1.0f);
          ++inside;
        }
        if (d >= 30.0) {
          EXPECT_EQ(v, 0.0f);
          ++outside;
        }
        if (d > 20.0 && d < 30.0) {
          EXPECT_NEAR(v, 1.0 - (d - 20.0) / 10.0, 1e-6);
        }
      }
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 100);
    // The principal point is the brightest place, not the image centre when they differ.
    const int pi = static_cast<int>(cam.cx()), pj = static_cast<int>(cam.cy());
    EXPECT_EQ(out.at<cv::Vec3f>(pj, pi)[0], 1.0f);
  }
}

}  // namespace
}  // namespace vdfx::effects
