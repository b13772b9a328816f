/// @file
/// @brief The angular blur on the sphere: an impulse spreads into a round spot of the right
/// angular size at any altitude (a blur of the equirect plane would be stretched), energy is kept,
/// the seam and the poles are crossed, and the per-pixel mix of levels stays close to the
/// constant blur.
#include "effects/equirect_blur.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "effects/coords.h"

namespace vdfx::effects {
namespace {

constexpr double kPi = 3.14159265358979323846;

double altitude(int y, int h) {
  return 0.5 * kPi - (y + 0.5) * kPi / h;
}

Eigen::Vector3d dir(int x, int y, int w, int h) {
  return to_unit({((x + 0.5) / w - 0.5) * 360.0, altitude(y, h) * 180.0 / kPi});
}

/// Solid-angle weighted sum of the green channel.
double energy(const cv::Mat& img) {
  double e = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x)
      e += img.at<cv::Vec3f>(y, x)[1] * std::cos(altitude(y, img.rows));
  return e;
}

struct Spread {
  double east, north;  //!< angular variances (radians^2) along the local east and north axes
};

/// Second moments of the blurred spot around the impulse's direction, in its tangent plane.
Spread spread(const cv::Mat& img, const Eigen::Vector3d& n0) {
  const Eigen::Vector3d up(0, 1, 0);
  // Local axes of the tangent plane at n0 (which axis is "east" does not matter here).
  const Eigen::Vector3d e = n0.cross(up).normalized();
  const Eigen::Vector3d n = e.cross(n0).normalized();
  double se = 0, sn = 0, sw = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const double v = img.at<cv::Vec3f>(y, x)[1] * std::cos(altitude(y, img.rows));
      if (v <= 0) continue;
      const Eigen::Vector3d d = dir(x, y, img.cols, img.rows);
      if (d.dot(n0) < 0.5) continue;  // far side: nothing should be there
      const double a = std::atan2(d.dot(e), d.dot(n0)), b = std::atan2(d.dot(n), d.dot(n0));
      se += v * a * a;
      sn += v * b * b;
      sw += v;
    }
  return {se / sw, sn / sw};
}

cv::Mat impulse(int w, int h, int x, int y) {
  cv::Mat m(h, w, CV_32FC3, cv::Scalar::all(0));
  m.at<cv::Vec3f>(y, x) = cv::Vec3f(1, 1, 1);
  return m;
}

TEST(EquirectBlur, ImpulseBecomesARoundSpotOfTheRightSizeAtAnyAltitude) {
  const int w = 720, h = 360;
  const double sigma_deg = 3.0, sigma = sigma_deg * kPi / 180.0;
  for (const int y : {180, 119, 59, 29}) {  // altitude ~0, 30, 60, 75 degrees
    const cv::Mat src = impulse(w, h, 250, y);
    const cv::Mat out = blur_equirect(src, sigma_deg);
    const Spread s = spread(out, dir(250, y, w, h));
    std::cout << "altitude " << altitude(y, h) * 180 / kPi << ": sigma east "
              << std::sqrt(s.east) * 180 / kPi << " deg, north " << std::sqrt(s.north) * 180 / kPi
              << " deg (asked " << sigma_deg << ")\n";
    // A 2-D Gaussian on the sphere: sigma^2 along each axis (plus the texel's own size).
    EXPECT_NEAR(std::sqrt(s.east), sigma, 0.09 * sigma) << "row " << y;
    EXPECT_NEAR(std::sqrt(s.north), sigma, 0.08 * sigma) << "row " << y;
    EXPECT_NEAR(energy(out), energy(src), 0.01 * energy(src)) << "row " << y;
  }
}

TEST(EquirectBlur, ConstantStaysConstantEverywhere) {
  const cv::Mat flat(90, 180, CV_32FC3, cv::Scalar(0.2, 0.5, 0.8));
  for (const double s : {0.7, 4.0, 20.0}) {
    const cv::Mat out = blur_equirect(flat, s);
    cv::Mat d;
    cv::absdiff(out, flat, d);
    double mx = 0;
    cv::minMaxLoc(d.reshape(1), nullptr, &mx);
    EXPECT_LT(mx, 1e-5) << s;
  }
}

TEST(EquirectBlur, CrossesTheSeamAndThePole) {
  const int w = 360, h = 180;
  // The seam is nowhere special: blurring the image turned by half a revolution gives the same
  // image turned.
  cv::Mat img(h, w, CV_32FC3);
  cv::randu(img, 0.0, 1.0);
  auto turn = [&](const cv::Mat& m) {
    cv::Mat t(m.size(), m.type());
    m.colRange(w / 2, w).copyTo(t.colRange(0, w / 2));
    m.colRange(0, w / 2).copyTo(t.colRange(w / 2, w));
    return t;
  };
  for (const double s : {0.8, 2.0, 7.0}) {
    cv::Mat d;
    cv::absdiff(turn(blur_equirect(img, s)), blur_equirect(turn(img), s), d);
    double mx = 0;
    cv::minMaxLoc(d.reshape(1), nullptr, &mx);
    EXPECT_LT(mx, 1e-5) << s;
  }
  // Next to the pole: the light reaches the other side of it (half a turn away in azimuth).
  const cv::Mat src = impulse(w, h, 10, 0);
  const cv::Mat pole = blur_equirect(src, 2.0);
  EXPECT_GT(pole.at<cv::Vec3f>(0, 10 + w / 2)[1], 0.0f);
  // Point light right at the pole: the reduced level and the per-pixel normalisation keep it
  // within 10% (1% for the impulses above).
  EXPECT_NEAR(energy(pole), energy(src), 0.1 * energy(src));
}

TEST(EquirectBlur, VaryingSigmaMixesLevelsCloseToTheConstantBlur) {
  const int w = 256, h = 128;
  cv::Mat img(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at<cv::Vec3f>(y, x) =
          ((x / 8 + y / 8) % 2) ? cv::Vec3f(0.9f, 0.8f, 0.1f) : cv::Vec3f(0.1f, 0.2f, 0.7f);
  // Zero sigma: untouched, exactly.
  const cv::Mat zero(h, w, CV_32FC1, cv::Scalar(0));
  cv::Mat d;
  cv::absdiff(blur_equirect_varying(img, zero), img, d);
  EXPECT_EQ(cv::countNonZero(d.reshape(1)), 0);
  // One sigma everywhere, between two levels: the mix against the exact constant blur.
  for (const double s : {1.0, 2.5, 6.0}) {
    const cv::Mat map(h, w, CV_32FC1, cv::Scalar(s));
    cv::absdiff(blur_equirect_varying(img, map), blur_equirect(img, s), d);
    const double rms = std::sqrt(cv::mean(d.mul(d))[1]);
    std::cout << "sigma " << s << " deg: level mix vs constant blur, RMS " << rms * 255 << "/255\n";
    EXPECT_LT(rms, 6.0 / 255.0) << s;
  }
}

TEST(EquirectBlur, VaryingSigmaEqualsTheMixOfWholeLevelsAtEveryPixel) {
  // The varying blur computes each level only where some pixel mixes it (tiles of the sigma map,
  // dilated by the read-back): every pixel must still get exactly the linear mix of the two
  // whole constant-blur levels around its sigma, whatever the neighbouring sigmas are.
  const int w = 256, h = 128;
  cv::Mat img(h, w, CV_32FC3);
  cv::randu(img, 0.0, 1.0);
  cv::Mat sigma(h, w, CV_32FC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)  // 0 (and below, clamped) on one side, up to 9 degrees, in steps
      sigma.at<float>(y, x) = static_cast<float>(
          std::max(-0.5, 9.0 * std::sin(kPi * x / w) * (y % 37 < 30 ? 1.0 : 0.3) - 1.0));
  sigma.at<float>(64, 20) = 6.0f;  // one lone pixel far above its neighbours
  const cv::Mat out = blur_equirect_varying(img, sigma);
  double max_sigma = 0.0;
  cv::minMaxLoc(sigma, nullptr, &max_sigma);
  std::vector<double> sigmas{0.0};
  std::vector<cv::Mat> levels{img};
  for (double s = 0.5 * 360.0 / w;; s *= 1.4142135623730951) {
    sigmas.push_back(s);
    levels.push_back(blur_equirect(img, s));
    if (s >= max_sigma) break;
  }
  double worst = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double s = std::max(0.0f, sigma.at<float>(y, x));
      cv::Vec3f expected = img.at<cv::Vec3f>(y, x);
      if (s > 0.0) {
        std::size_t k = 1;
        while (k + 1 < sigmas.size() && sigmas[k] < s) ++k;
        const float t = static_cast<float>((s - sigmas[k - 1]) / (sigmas[k] - sigmas[k - 1]));
        expected =
            levels[k - 1].at<cv::Vec3f>(y, x) * (1.0f - t) + levels[k].at<cv::Vec3f>(y, x) * t;
      }
      const double e = cv::norm(out.at<cv::Vec3f>(y, x) - expected, cv::NORM_INF);
      worst = std::max(worst, e);
    }
  std::cout << "varying map against whole levels: max difference " << worst << "\n";
  EXPECT_LT(worst, 1e-5);
}

TEST(EquirectBlur, AHalfTurnIsClampedAtItsEdgesNeverWrapped) {
  // A VR180 image (azimuth -90..90): a constant stays constant; a bright left edge spreads
  // inwards but never reaches the right edge (a 360 blur of the same pixels wraps it there);
  // near a pole the light crosses over, as on the sphere.
  const int w = 128, h = 128;
  const cv::Mat flat(h, w, CV_32FC3, cv::Scalar(0.2, 0.5, 0.8));
  const cv::Mat sigma(h, w, CV_32FC1, cv::Scalar(4.0f));
  cv::Mat out, d;
  blur_half_equirect_varying(flat, sigma, out);
  cv::absdiff(out, flat, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  EXPECT_LT(mx, 1e-5);
  cv::Mat edge(h, w, CV_32FC3, cv::Scalar::all(0));
  edge.colRange(0, 4).setTo(cv::Scalar::all(1));
  blur_half_equirect_varying(edge, sigma, out);
  const cv::Mat wrapped = blur_equirect_varying(edge, sigma);
  EXPECT_GT(out.at<cv::Vec3f>(h / 2, 5)[1], 0.2f);           // spread inwards
  EXPECT_LT(out.at<cv::Vec3f>(h / 2, w - 1)[1], 1e-6f);      // never across the edge
  EXPECT_GT(wrapped.at<cv::Vec3f>(h / 2, w - 1)[1], 0.05f);  // where a whole turn wraps
  EXPECT_GT(out.at<cv::Vec3f>(0, w - 1)[1], 0.0f);           // across the pole
}

}  // namespace
}  // namespace vdfx::effects
