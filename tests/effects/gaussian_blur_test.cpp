/// @file
/// @brief Gaussian blur: kernel, the three peers agree, point spread in degrees, varying gather.
#include "effects/gaussian_blur.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <opencv2/core.hpp>

#include "effects/effect_stack.h"
#include "effects/view_camera.h"

namespace vdfx::effects {
namespace {

TEST(GaussianBlur, KernelHasRadiusCeil3SigmaAndSumsToOne) {
  const struct {
    double sigma;
    int radius;
  } rows[] = {{0.0, 0}, {0.2, 1}, {1.0, 3}, {1.01, 4}, {2.5, 8}, {10.0, 30}};
  for (const auto& r : rows) {
    EXPECT_EQ(gaussian_radius(r.sigma), r.radius) << r.sigma;
    const auto k = gaussian_kernel(r.sigma);
    ASSERT_EQ(k.size(), static_cast<size_t>(2 * r.radius + 1));
    double sum = 0.0;
    for (double v : k) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-15);
    if (r.radius > 0) {
      EXPECT_DOUBLE_EQ(k.front(), k.back());
      const size_t c = static_cast<size_t>(r.radius);
      EXPECT_NEAR(k[c + 1] / k[c], std::exp(-0.5 / (r.sigma * r.sigma)), 1e-14);
    }
  }
}

TEST(GaussianBlur, ExactSeparableAndOpenCvAgree) {
  cv::Mat img(45, 61, CV_32FC3);
  cv::randu(img, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  for (const auto& s : {cv::Vec2d(0.7, 0.7), cv::Vec2d(2.3, 1.4), cv::Vec2d(4.0, 0.0)}) {
    const cv::Mat exact = blur_exact_2d(img, s[0], s[1]);
    EXPECT_LT(cv::norm(blur_separable(img, s[0], s[1]), exact, cv::NORM_INF), 2e-6) << s;
    EXPECT_LT(cv::norm(blur_opencv(img, s[0], s[1]), exact, cv::NORM_INF), 2e-5) << s;
    EXPECT_GT(cv::norm(exact, img, cv::NORM_INF), 0.05) << "the blur did something";
  }
  EXPECT_EQ(cv::norm(blur_separable(img, 0.0, 0.0), img, cv::NORM_INF), 0.0);
}

// Fits ln I = a - theta^2 / (2 s^2) to the centre row within 2 sigma; returns s in degrees.
double fitted_sigma_deg(const cv::Mat& img, const ViewCamera& cam, double sigma_px) {
  const int row = static_cast<int>(cam.cy());
  const int centre = static_cast<int>(cam.cx());
  const int half = std::max(1, static_cast<int>(2.0 * sigma_px));
  Eigen::MatrixXd a(2 * half + 1, 2);
  Eigen::VectorXd b(2 * half + 1);
  for (int k = -half; k <= half; ++k) {
    const double theta_deg = std::atan((centre + k + 0.5 - cam.cx()) / cam.fx()) * kRadToDeg;
    a(k + half, 0) = 1.0;
    a(k + half, 1) = theta_deg * theta_deg;
    b(k + half) = std::log(img.at<cv::Vec3f>(row, centre + k)[0]);
  }
  const Eigen::Vector2d coef = a.colPivHouseholderQr().solve(b);
  return std::sqrt(-0.5 / coef(1));
}

TEST(GaussianBlur, PointSpreadHasTheRequestedSigmaInDegrees) {
  for (double fov : {60.0, 110.0}) {
    const ViewCamera cam = ViewCamera::from_horizontal_fov({{0, 0}, 0}, fov, 301, 301);
    for (double sigma_deg : {0.5, 1.0, 2.5, 6.0}) {
      cv::Mat point(301, 301, CV_32FC3, cv::Scalar::all(0.0));
      point.at<cv::Vec3f>(150, 150) = cv::Vec3f(1, 1, 1);
      StackParams p;
      p.blur_sigma_deg = sigma_deg;
      const cv::Mat out = apply_stack(point, p, cam);
      const double sigma_px = sigma_px_from_deg(sigma_deg, cam.fx());
      EXPECT_NEAR(fitted_sigma_deg(out, cam, sigma_px), sigma_deg, 0.02 * sigma_deg)
          << "fov " << fov << " sigma " << sigma_deg;
      EXPECT_NEAR(cv::sum(out)[0], 1.0, 1e-5);  // energy is kept
    }
  }
}

TEST(GaussianBlur, VaryingGatherWithConstantSigmaIsTheSeparableBlur) {
  const int margin = 9;
  cv::Mat src(30 + 2 * margin, 40 + 2 * margin, CV_32FC3);
  cv::randu(src, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  const cv::Mat sigma(30, 40, CV_64FC2, cv::Scalar(2.9, 1.7));
  const cv::Mat got = blur_varying(src, margin, sigma);
  const cv::Mat want = blur_separable(src, 2.9, 1.7)(cv::Rect(margin, margin, 40, 30));
  EXPECT_LT(cv::norm(got, want, cv::NORM_INF), 2e-6);
  // Zero sigma copies the pixel.
  const cv::Mat none = blur_varying(src, margin, cv::Mat(30, 40, CV_64FC2, cv::Scalar(0, 0)));
  EXPECT_EQ(cv::norm(none, src(cv::Rect(margin, margin, 40, 30)), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace vdfx::effects
