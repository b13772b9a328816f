/// @file
/// @brief The CPU reference view renderer (see view_renderer.h).
#include "effects/view_renderer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "effects/effect_stack.h"
#include "effects/gaussian_blur.h"

namespace vdfx::effects {

cv::Mat sample_view(const EquirectSampler& sampler, const ViewCamera& camera) {
  cv::Mat out(camera.height(), camera.width(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, camera.height()), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      auto* o = out.ptr<cv::Vec3f>(j);
      for (int i = 0; i < camera.width(); ++i) {
        const Eigen::Vector3d c = sampler.sample_pixel(camera, i + 0.5, j + 0.5);
        o[i] = cv::Vec3f(static_cast<float>(c.x()), static_cast<float>(c.y()),
                         static_cast<float>(c.z()));
      }
    }
  });
  return out;
}

namespace {

cv::Mat crop(const cv::Mat& img, int margin) {
  return img(cv::Rect(margin, margin, img.cols - 2 * margin, img.rows - 2 * margin)).clone();
}

cv::Mat render_pixel_mode(const EquirectSampler& sampler, const ViewCamera& camera,
                          const ParamsAt& params_at) {
  const int w = camera.width(), h = camera.height();
  std::vector<StackParams> params(static_cast<size_t>(w) * static_cast<size_t>(h));
  cv::Mat sigma(h, w, CV_64FC2, cv::Scalar(0, 0));
  int margin = 0;
  bool any_blur = false;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      StackParams& p = params[static_cast<size_t>(j) * w + i];
      p = params_at(from_unit(camera.pixel_ray(i, j)));
      if (p.is_neutral(EffectType::Blur)) continue;
      const Eigen::Vector2d s = blur_sigma_px(camera, p.blur_sigma_deg);
      sigma.at<cv::Vec2d>(j, i) = cv::Vec2d(s.x(), s.y());
      margin = std::max({margin, gaussian_radius(s.x()), gaussian_radius(s.y())});
      any_blur = true;
    }
  }
  const cv::Mat base =
      any_blur ? blur_varying(sample_view(sampler, camera.with_margin(margin)), margin, sigma)
               : sample_view(sampler, camera);
  const cv::Mat angles = vignette_angle_map(camera);
  cv::Mat out(h, w, CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      const auto* in = base.ptr<cv::Vec3f>(j);
      auto* o = out.ptr<cv::Vec3f>(j);
      for (int i = 0; i < w; ++i) {
        const Eigen::Vector3d c =
            apply_colour_stack(Eigen::Vector3d(in[i][0], in[i][1], in[i][2]),
                               params[static_cast<size_t>(j) * w + i], angles.at<double>(j, i));
        o[i] = cv::Vec3f(static_cast<float>(c.x()), static_cast<float>(c.y()),
                         static_cast<float>(c.z()));
      }
    }
  });
  return out;
}

}  // namespace

cv::Mat render_view(const EquirectSampler& sampler, const ViewCamera& camera,
                    const StackParams& params) {
  cv::Mat base;
  if (params.is_neutral(EffectType::Blur)) {
    base = sample_view(sampler, camera);
  } else {
    const Eigen::Vector2d s = blur_sigma_px(camera, params.blur_sigma_deg);
    const int margin = std::max(gaussian_radius(s.x()), gaussian_radius(s.y()));
    base = crop(blur_separable(sample_view(sampler, camera.with_margin(margin)), s.x(), s.y()),
                margin);
  }
  return apply_colour_stack(base, params, vignette_angle_map(camera));
}

cv::Mat render_view(const EquirectSampler& sampler, const ViewCamera& camera,
                    const ParamsAt& params_at, RenderMode mode) {
  if (!params_at) throw std::invalid_argument("render_view: empty parameter function");
  if (mode == RenderMode::View)
    return render_view(sampler, camera, params_at(camera.centre_direction()));
  return render_pixel_mode(sampler, camera, params_at);
}

cv::Mat to_rgb8(const cv::Mat& rgb) {
  if (rgb.empty() || rgb.type() != CV_32FC3)
    throw std::invalid_argument("to_rgb8: need a non-empty CV_32FC3 image");
  cv::Mat out(rgb.size(), CV_8UC3);
  for (int j = 0; j < rgb.rows; ++j) {
    const auto* in = rgb.ptr<cv::Vec3f>(j);
    auto* o = out.ptr<cv::Vec3b>(j);
    for (int i = 0; i < rgb.cols; ++i) {
      for (int k = 0; k < 3; ++k) {
        const double v = in[i][k];
        // NaN fails both comparisons and lands on 0.
        const double c = v > 1.0 ? 1.0 : (v >= 0.0 ? v : 0.0);
        o[i][k] = static_cast<unsigned char>(std::floor(c * 255.0 + 0.5));
      }
    }
  }
  return out;
}

}  // namespace vdfx::effects
