/// @file
/// @brief CPU reference of the shader grain styles: the plane and sphere geometry per eye, the
/// surface grain fixed in the world and the headset grain fixed to the head, no pinch at the
/// pole, intensity.
#include "effects/grain_render.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "effects/view_camera.h"

namespace vdfx::effects {
namespace {

// Size 2 by default: at kFov's density (667 px per tangent unit, 1.5 mrad per pixel) a lattice
// cell is 5 px wide, so no octave is band-limited and the grain is exactly world-fixed.
GrainFrame frame(GrainStyle style, double intensity, const HeadPose& head, double size = 2.0) {
  GrainEffect e;
  e.style = style;
  e.seed = 17;
  e.keyframes = {{{0, 0}, 0, {intensity, size}}};
  GrainSet set({e}, {}, 30.0);
  auto frames = set.layout(head, 40'000'000, 0);
  EXPECT_EQ(frames.size(), 1u);
  // Parameters are taken at the head's forward direction; constant keyframes make them fixed.
  return frames.at(0);
}

Eigen::Matrix3d yaw(double deg) {
  return Eigen::AngleAxisd(-deg * kDegToRad, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

const TanRect kFov{-0.16, 0.14, 0.12, -0.12};

/// Grain modulation s at a fractional fragment position of a 200x160 eye.
float at(const GrainFrame& f, const Eigen::Matrix3d& eye_rot, const Eigen::Vector3d& eye, double fx,
         double fy) {
  const ShaderGrainUniforms u = shader_grain_uniforms(f, eye_rot, eye, kFov);
  const std::optional<float> s = shader_grain_fragment(u, *f.noise, float(fx), float(fy), 200, 160);
  EXPECT_TRUE(s.has_value());
  return s.value_or(std::nanf(""));
}

TEST(GrainRender, HeadsetNoiseIsEvaluatedOnThePlaneAheadOfTheHead) {
  HeadPose head;
  head.position = {0.3, 1.6, -0.2};
  head.orientation = yaw(25) * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const GrainFrame f = frame(GrainStyle::Headset, 0.4, head);
  const Eigen::Vector3d eye = head.position + head.orientation * Eigen::Vector3d(-0.0315, 0, 0);
  // Independent double-precision geometry for a few pixels: ray, plane hit in head coordinates.
  for (const auto& px :
       {Eigen::Vector2d(10.5, 20.5), Eigen::Vector2d(100.5, 80.5), Eigen::Vector2d(190.5, 150.5)}) {
    const double tx = kFov.left + px.x() / 200 * (kFov.right - kFov.left);
    const double ty = kFov.down + px.y() / 160 * (kFov.up - kFov.down);
    const Eigen::Vector3d d = head.orientation * Eigen::Vector3d(tx, ty, -1).normalized();
    const Eigen::Vector3d e_h = head.orientation.transpose() * (eye - head.position);
    const Eigen::Vector3d d_h = head.orientation.transpose() * d;
    const double t = (-0.05 - e_h.z()) / d_h.z();
    const Eigen::Vector3d q = (e_h + t * d_h) / f.cell_m;
    const auto n = [&](const Eigen::Vector3d& p) {
      return (*f.noise)(float(p.x()), float(p.y()), float(p.z()));
    };
    const double g = n(Eigen::Vector3d(q.x(), q.y(), 0) + f.noise_offset[0]) +
                     0.5 * n(Eigen::Vector3d(2 * q.x(), 2 * q.y(), 0) + f.noise_offset[1]);
    EXPECT_NEAR(at(f, head.orientation, eye, px.x(), px.y()), std::max(-1.0, 0.4 * kGrainGain * g),
                1e-3)
        << px.transpose();
  }
}

TEST(GrainRender, SurfaceGrainStaysPutInTheWorldWhenTheHeadTurns) {
  HeadPose a, b;
  b.orientation = yaw(5);
  const GrainFrame fa = frame(GrainStyle::Surface, 0.5, a), fb = frame(GrainStyle::Surface, 0.5, b);
  const ViewCamera cam_a = ViewCamera::from_tangents(a.orientation, kFov, 200, 160);
  const ViewCamera cam_b = ViewCamera::from_tangents(b.orientation, kFov, 200, 160);
  int compared = 0;
  double worst = 0.0;
  for (int j = 5; j < 160; j += 10)
    for (int i = 100; i < 200; i += 7) {
      // The world direction of pixel (i, j) in view a, found again in view b.
      const Eigen::Vector3d ray = cam_a.pixel_ray(i, j);
      const auto pb = cam_b.project(ray);
      if (!pb || pb->x() < 0 || pb->x() >= 200) continue;
      const float va = at(fa, a.orientation, a.position, i + 0.5, 160 - (j + 0.5));
      const float vb = at(fb, b.orientation, b.position, pb->x(), 160 - pb->y());
      worst = std::max(worst, double(std::abs(va - vb)));
      ++compared;
    }
  EXPECT_GT(compared, 50);
  EXPECT_LT(worst, 2e-3);
  // The headset grain, by contrast, turns with the head: the same world direction differs.
  const GrainFrame ha = frame(GrainStyle::Headset, 0.5, a), hb = frame(GrainStyle::Headset, 0.5, b);
  double moved = 0.0;
  for (int i = 100; i < 200; i += 3) {
    const auto pb = cam_b.project(cam_a.pixel_ray(i, 80));
    moved += std::abs(at(ha, a.orientation, a.position, i + 0.5, 79.5) -
                      at(hb, b.orientation, b.position, pb->x(), 160 - pb->y()));
  }
  EXPECT_GT(moved, 0.5);
}

TEST(GrainRender, HeadsetGrainIsFixedToTheHead) {
  HeadPose a, b;
  a.position = {0, 1.6, 0};
  b.position = {1, 1.5, 2};
  b.orientation = yaw(70) * Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const GrainFrame fa = frame(GrainStyle::Headset, 0.7, a), fb = frame(GrainStyle::Headset, 0.7, b);
  const Eigen::Vector3d off(0.0315, 0, 0);
  for (int j = 0; j < 160; j += 9)
    for (int i = 0; i < 200; i += 11) {
      const float va = at(fa, a.orientation, a.position + a.orientation * off, i + .5, j + .5);
      const float vb = at(fb, b.orientation, b.position + b.orientation * off, i + .5, j + .5);
      ASSERT_NEAR(va, vb, 1e-3) << i << "," << j;
    }
}

/// Mean change and mean difference of horizontal neighbours of a layer rendered on grey.
std::pair<double, double> texture_stats(const GrainFrame& f, const Eigen::Matrix3d& rot,
                                        const TanRect& fov = kFov) {
  cv::Mat img(160, 200, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  composite_shader_grain(img, f, rot, Eigen::Vector3d::Zero(), fov);
  double level = 0, step = 0;
  for (int j = 0; j < img.rows; ++j)
    for (int i = 1; i < img.cols; ++i) {
      level += std::abs(img.at<cv::Vec3f>(j, i)[0] - 0.5);
      step += std::abs(img.at<cv::Vec3f>(j, i)[0] - img.at<cv::Vec3f>(j, i - 1)[0]);
    }
  return {level / (160 * 199), step / (160 * 199)};
}

TEST(GrainRender, SurfaceGrainLooksTheSameAtThePoleAsAtTheHorizon) {
  // Noise in 3-D on the sphere: no pinch at the pole, where an equirect parametrisation would
  // shrink its cells to nothing (and a seam at the back).
  HeadPose h;
  const GrainFrame f = frame(GrainStyle::Surface, 0.5, h);
  const auto horizon = texture_stats(f, Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d up =
      Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const auto pole = texture_stats(f, up);
  const auto seam = texture_stats(f, yaw(180));
  EXPECT_GT(horizon.first, 0.02);
  EXPECT_NEAR(pole.first / horizon.first, 1.0, 0.15);
  EXPECT_NEAR(pole.second / horizon.second, 1.0, 0.15);
  EXPECT_NEAR(seam.second / horizon.second, 1.0, 0.15);
}

TEST(GrainRender, IntensityScalesTheLayerAndZeroLeavesTheImage) {
  HeadPose h;
  const GrainFrame weak = frame(GrainStyle::Surface, 0.1, h),
                   strong = frame(GrainStyle::Surface, 0.4, h);
  const auto a = texture_stats(weak, Eigen::Matrix3d::Identity());
  const auto b = texture_stats(strong, Eigen::Matrix3d::Identity());
  EXPECT_NEAR(b.first / a.first, 4.0, 0.4);  // s = max(-1, I * gain * g): linear above -1
  // The change is s (C + floor): twice as strong on a colour twice as bright (plus the floor).
  cv::Mat dark(160, 200, CV_32FC3, cv::Scalar(0.2, 0.2, 0.2)),
      light(160, 200, CV_32FC3, cv::Scalar(0.4, 0.4, 0.4));
  composite_shader_grain(dark, strong, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), kFov);
  composite_shader_grain(light, strong, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), kFov);
  const double ratio = cv::norm(light - cv::Scalar(0.4, 0.4, 0.4), cv::NORM_L1) /
                       cv::norm(dark - cv::Scalar(0.2, 0.2, 0.2), cv::NORM_L1);
  EXPECT_NEAR(ratio, (0.4 + kGrainFloor) / (0.2 + kGrainFloor), 1e-3);
  // Intensity 0 gives no layer at all (GrainSet skips it), and a frame forced to 0 draws nothing.
  GrainFrame zero = weak;
  zero.params.intensity = 0.0;
  cv::Mat img(160, 200, CV_32FC3, cv::Scalar(0.25, 0.5, 0.75));
  const cv::Mat before = img.clone();
  composite_shader_grain(img, zero, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), kFov);
  EXPECT_EQ(cv::norm(img, before, cv::NORM_INF), 0.0);
  GrainFrame cloud = weak;
  cloud.style = GrainStyle::FreeCloud;
  EXPECT_THROW(composite_shader_grain(img, cloud, Eigen::Matrix3d::Identity(),
                                      Eigen::Vector3d::Zero(), kFov),
               std::invalid_argument);
}

TEST(GrainRender, GrainFinerThanAPixelFadesInsteadOfAliasing) {
  // The same grain (size 1, sphere 10 m: 4 mrad cells) seen at falling pixel densities: each
  // octave fades out between 0.5 and 1 lattice cells per pixel, so coarse eyes get less grain,
  // never a moire of undersampled noise; past 1 cell per pixel for both octaves, none at all.
  HeadPose h;
  const GrainFrame f = frame(GrainStyle::Surface, 0.5, h, 1.0);
  double previous = 1e9;
  for (double scale : {1.0, 2.0, 3.0, 4.0, 6.0}) {
    const TanRect fov{kFov.left * scale, kFov.right * scale, kFov.up * scale, kFov.down * scale};
    const double level = texture_stats(f, Eigen::Matrix3d::Identity(), fov).first;
    // 1.5 mrad per pixel at scale 1: 0.375 cells per pixel; scale 4: 1.5 at the centre, 1.3 in
    // the corners (where pixels span smaller angles), nothing left.
    if (scale >= 4.0)
      EXPECT_EQ(level, 0.0) << scale;
    else
      EXPECT_GT(level, 0.0) << scale;
    EXPECT_LE(level, previous) << scale;
    previous = level;
  }
  // At scale 1 the second octave is half faded (0.375 cells per pixel for octave 1, 0.75 for
  // octave 2): less grain than the same grain at twice the size, where neither fades.
  const double full =
      texture_stats(frame(GrainStyle::Surface, 0.5, h, 2.0), Eigen::Matrix3d::Identity()).first;
  EXPECT_LT(texture_stats(f, Eigen::Matrix3d::Identity()).first, full);
}

}  // namespace
}  // namespace vdfx::effects
