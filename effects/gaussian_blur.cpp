/// @file
/// @brief Gaussian blur implementations (see gaussian_blur.h).
#include "effects/gaussian_blur.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "effects/coords.h"

namespace vdfx::effects {

namespace {
void check_rgb(const cv::Mat& src, const char* where) {
  if (src.empty() || src.type() != CV_32FC3)
    throw std::invalid_argument(std::string(where) + ": need a non-empty CV_32FC3 image");
}
}  // namespace

int gaussian_radius(double sigma_px) {
  return sigma_px > 0.0 ? static_cast<int>(std::ceil(3.0 * sigma_px)) : 0;
}

std::vector<double> gaussian_kernel(double sigma_px) {
  const int r = gaussian_radius(sigma_px);
  if (r == 0) return {1.0};
  std::vector<double> w(static_cast<size_t>(2 * r + 1));
  double sum = 0.0;
  for (int i = -r; i <= r; ++i) {
    const double v = std::exp(-0.5 * i * i / (sigma_px * sigma_px));
    w[static_cast<size_t>(i + r)] = v;
    sum += v;
  }
  for (double& v : w) v /= sum;
  return w;
}

double sigma_px_from_deg(double sigma_deg, double focal_px) {
  return focal_px * sigma_deg * kDegToRad;
}

cv::Mat blur_separable(const cv::Mat& src, double sigma_x_px, double sigma_y_px) {
  check_rgb(src, "blur_separable");
  const std::vector<double> kx = gaussian_kernel(sigma_x_px), ky = gaussian_kernel(sigma_y_px);
  const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
  const int w = src.cols, h = src.rows;
  cv::Mat tmp(h, w, CV_64FC3), dst(h, w, CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const auto* in = src.ptr<cv::Vec3f>(y);
      auto* out = tmp.ptr<cv::Vec3d>(y);
      for (int x = 0; x < w; ++x) {
        cv::Vec3d acc(0, 0, 0);
        for (int k = -rx; k <= rx; ++k) {
          const cv::Vec3f& p = in[std::clamp(x + k, 0, w - 1)];
          const double wk = kx[static_cast<size_t>(k + rx)];
          acc[0] += wk * p[0];
          acc[1] += wk * p[1];
          acc[2] += wk * p[2];
        }
        out[x] = acc;
      }
    }
  });
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    std::vector<cv::Vec3d> acc(static_cast<size_t>(w));
    for (int y = rows.start; y < rows.end; ++y) {
      std::fill(acc.begin(), acc.end(), cv::Vec3d(0, 0, 0));
      for (int k = -ry; k <= ry; ++k) {
        const auto* in = tmp.ptr<cv::Vec3d>(std::clamp(y + k, 0, h - 1));
        const double wk = ky[static_cast<size_t>(k + ry)];
        for (int x = 0; x < w; ++x) acc[static_cast<size_t>(x)] += wk * in[x];
      }
      auto* out = dst.ptr<cv::Vec3f>(y);
      for (int x = 0; x < w; ++x) out[x] = cv::Vec3f(acc[static_cast<size_t>(x)]);
    }
  });
  return dst;
}

cv::Mat blur_exact_2d(const cv::Mat& src, double sigma_x_px, double sigma_y_px) {
  check_rgb(src, "blur_exact_2d");
  const std::vector<double> kx = gaussian_kernel(sigma_x_px), ky = gaussian_kernel(sigma_y_px);
  const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
  const int w = src.cols, h = src.rows;
  cv::Mat dst(h, w, CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      auto* out = dst.ptr<cv::Vec3f>(y);
      for (int x = 0; x < w; ++x) {
        cv::Vec3d acc(0, 0, 0);
        for (int j = -ry; j <= ry; ++j) {
          const auto* in = src.ptr<cv::Vec3f>(std::clamp(y + j, 0, h - 1));
          const double wy = ky[static_cast<size_t>(j + ry)];
          for (int i = -rx; i <= rx; ++i) {
            const double wgt = wy * kx[static_cast<size_t>(i + rx)];
            const cv::Vec3f& p = in[std::clamp(x + i, 0, w - 1)];
            acc[0] += wgt * p[0];
            acc[1] += wgt * p[1];
            acc[2] += wgt * p[2];
          }
        }
        out[x] = cv::Vec3f(acc);
      }
    }
  });
  return dst;
}

cv::Mat blur_opencv(const cv::Mat& src, double sigma_x_px, double sigma_y_px) {
  check_rgb(src, "blur_opencv");
  if (sigma_x_px <= 0.0 && sigma_y_px <= 0.0) return src.clone();
  // OpenCV reads sigma 0 as "derive from the kernel size": a 1-wide kernel must stay identity.
  const double sx = sigma_x_px > 0.0 ? sigma_x_px : 1e-9;
  const double sy = sigma_y_px > 0.0 ? sigma_y_px : 1e-9;
  cv::Mat dst;
  cv::GaussianBlur(
      src, dst, cv::Size(2 * gaussian_radius(sigma_x_px) + 1, 2 * gaussian_radius(sigma_y_px) + 1),
      sx, sy, cv::BORDER_REPLICATE);
  return dst;
}

cv::Mat blur_varying(const cv::Mat& src, int margin, const cv::Mat& sigma_px) {
  check_rgb(src, "blur_varying");
  const int w = src.cols - 2 * margin, h = src.rows - 2 * margin;
  if (margin < 0 || w <= 0 || h <= 0 || sigma_px.type() != CV_64FC2 || sigma_px.cols != w ||
      sigma_px.rows != h)
    throw std::invalid_argument(
        "blur_varying: need CV_64FC2 sigmas of the source size minus the margin");
  cv::Mat dst(h, w, CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      auto* out = dst.ptr<cv::Vec3f>(y);
      const auto* sig = sigma_px.ptr<cv::Vec2d>(y);
      for (int x = 0; x < w; ++x) {
        const double sx = sig[x][0], sy = sig[x][1];
        const int rx = std::min(gaussian_radius(sx), margin);
        const int ry = std::min(gaussian_radius(sy), margin);
        cv::Vec3d acc(0, 0, 0);
        double sum = 0.0;
        for (int j = -ry; j <= ry; ++j) {
          const auto* in = src.ptr<cv::Vec3f>(y + margin + j);
          const double wy = ry > 0 ? std::exp(-0.5 * j * j / (sy * sy)) : 1.0;
          for (int i = -rx; i <= rx; ++i) {
            const double wgt = wy * (rx > 0 ? std::exp(-0.5 * i * i / (sx * sx)) : 1.0);
            const cv::Vec3f& p = in[x + margin + i];
            acc[0] += wgt * p[0];
            acc[1] += wgt * p[1];
            acc[2] += wgt * p[2];
            sum += wgt;
          }
        }
        out[x] = cv::Vec3f(acc / sum);
      }
    }
  });
  return dst;
}

}  // namespace vdfx::effects
