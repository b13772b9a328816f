/// @file
/// @brief The effect stack's formulas, per pixel and per image.
#include "effects/effect_stack.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "effects/gaussian_blur.h"

namespace vdfx::effects {

Eigen::Vector3d apply_tint(const Eigen::Vector3d& c, const Eigen::Vector3d& gain) {
  return c.cwiseProduct(gain);
}

Eigen::Vector3d apply_exposure(const Eigen::Vector3d& c, double stops) {
  return c * std::exp2(stops);
}

Eigen::Vector3d apply_saturation(const Eigen::Vector3d& c, double amount) {
  const double y = kLumaR * c.x() + kLumaG * c.y() + kLumaB * c.z();
  return (Eigen::Vector3d::Constant(y) + amount * (c - Eigen::Vector3d::Constant(y))).eval();
}

Eigen::Vector3d apply_contrast(const Eigen::Vector3d& c, double amount) {
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5);
  return (half + amount * (c - half)).eval();
}

double vignette_factor(double d_deg, double radius_deg, double falloff_deg) {
  if (d_deg <= radius_deg) return 1.0;
  if (falloff_deg > 0.0 && d_deg <= radius_deg + falloff_deg)
    return 1.0 - (d_deg - radius_deg) / falloff_deg;
  return 0.0;
}

Eigen::Vector3d apply_vignette(const Eigen::Vector3d& c, double d_deg, double radius_deg,
                               double falloff_deg) {
  const double f = vignette_factor(d_deg, radius_deg, falloff_deg);
  const Eigen::Vector3d black = Eigen::Vector3d::Zero();
  return (c * f + (1.0 - f) * black).eval();
}

Eigen::Vector3d apply_colour_stack(const Eigen::Vector3d& c, const StackParams& p,
                                   double vignette_angle_deg) {
  Eigen::Vector3d out = c;
  if (!p.is_neutral(EffectType::Tint)) out = apply_tint(out, p.tint_gain);
  if (!p.is_neutral(EffectType::Exposure)) out = apply_exposure(out, p.exposure_stops);
  if (!p.is_neutral(EffectType::Saturation)) out = apply_saturation(out, p.saturation);
  if (!p.is_neutral(EffectType::Contrast)) out = apply_contrast(out, p.contrast);
  if (!p.is_neutral(EffectType::Vignette))
    out = apply_vignette(out, vignette_angle_deg, p.vignette_radius_deg, p.vignette_falloff_deg);
  return out;
}

Eigen::Vector3d clamp_output(const Eigen::Vector3d& c) {
  return c.cwiseMax(0.0).cwiseMin(1.0);
}

cv::Mat vignette_angle_map(const ViewCamera& camera) {
  cv::Mat angles(camera.height(), camera.width(), CV_64FC1);
  const Eigen::Vector3d axis = camera.optical_axis();
  cv::parallel_for_(cv::Range(0, camera.height()), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      auto* out = angles.ptr<double>(j);
      for (int i = 0; i < camera.width(); ++i)
        out[i] = angle_between(camera.pixel_ray(i, j), axis) * kRadToDeg;
    }
  });
  return angles;
}

Eigen::Vector2d blur_sigma_px(const ViewCamera& camera, double sigma_deg) {
  return {sigma_px_from_deg(sigma_deg, camera.fx()), sigma_px_from_deg(sigma_deg, camera.fy())};
}

cv::Mat apply_colour_stack(const cv::Mat& rgb, const StackParams& p, const cv::Mat& angle_deg) {
  if (rgb.empty() || rgb.type() != CV_32FC3)
    throw std::invalid_argument("apply_colour_stack: need a non-empty CV_32FC3 image");
  if (angle_deg.type() != CV_64FC1 || angle_deg.size() != rgb.size())
    throw std::invalid_argument("apply_colour_stack: angle map must be CV_64FC1 of the image size");
  cv::Mat out(rgb.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      const auto* in = rgb.ptr<cv::Vec3f>(j);
      const auto* ang = angle_deg.ptr<double>(j);
      auto* o = out.ptr<cv::Vec3f>(j);
      for (int i = 0; i < rgb.cols; ++i) {
        const Eigen::Vector3d c =
            apply_colour_stack(Eigen::Vector3d(in[i][0], in[i][1], in[i][2]), p, ang[i]);
        o[i] = cv::Vec3f(static_cast<float>(c.x()), static_cast<float>(c.y()),
                         static_cast<float>(c.z()));
      }
    }
  });
  return out;
}

cv::Mat apply_stack(const cv::Mat& rgb, const StackParams& p, const ViewCamera& camera) {
  if (rgb.cols != camera.width() || rgb.rows != camera.height())
    throw std::invalid_argument("apply_stack: image and camera sizes differ");
  cv::Mat blurred = rgb;
  if (!p.is_neutral(EffectType::Blur)) {
    const Eigen::Vector2d s = blur_sigma_px(camera, p.blur_sigma_deg);
    blurred = blur_separable(rgb, s.x(), s.y());
  }
  return apply_colour_stack(blurred, p, vignette_angle_map(camera));
}

}  // namespace vdfx::effects
