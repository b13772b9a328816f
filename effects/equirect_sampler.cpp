/// @file
/// @brief EquirectSampler: bilinear and ripmap (area-aware) sampling of equirect images.
#include "effects/equirect_sampler.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "effects/coords.h"
#include "effects/stereo_layout.h"

namespace vdfx::effects {

Eigen::Vector2d direction_to_uv(const Eigen::Vector3d& dir) {
  // Same as to_equirect_uv(from_unit(dir)) without the degree round trip; azimuth 180 maps to
  // u = 1, which wraps onto column 0's side of the seam exactly as u = 0 does.
  const double horizontal = std::hypot(dir.x(), dir.z());
  const double az = horizontal > 0.0 ? std::atan2(dir.x(), -dir.z()) : 0.0;
  const double alt = std::atan2(dir.y(), horizontal);
  return {0.5 + az / (2.0 * kPi), 0.5 - alt / kPi};
}

cv::Mat eye_image(const cv::Mat& frame, const StereoLayout& layout, EyeIndex eye) {
  const PixelRect r = eye_rect(layout, eye, frame.cols, frame.rows);
  return frame(cv::Rect(r.x, r.y, r.width, r.height));
}

SamplerOptions sampler_options_for(const StereoLayout& layout, SamplerOptions base) {
  base.coverage_deg = layout.coverage_deg;
  return base;
}

EquirectSampler::EquirectSampler(const cv::Mat& equirect, SamplerOptions options)
    : options_(options), width_(equirect.cols), height_(equirect.rows) {
  if (equirect.empty() || equirect.type() != CV_32FC3)
    throw std::invalid_argument("EquirectSampler: need a non-empty CV_32FC3 RGB image");
  if (options_.coverage_deg != 360 && options_.coverage_deg != 180)
    throw std::invalid_argument("EquirectSampler: coverage must be 360 or 180");
  // A half sphere has no continuation across the pole inside the image.
  if (options_.coverage_deg != 360) options_.pole_rows = PoleRows::Clamp;
  levels_.push_back({equirect});
  if (options_.filter != SampleFilter::AreaAware) return;
  while ((width_ >> (max_lx_ + 1)) >= 1) ++max_lx_;
  while ((height_ >> (max_ly_ + 1)) >= 1) ++max_ly_;
  max_ly_ = std::min(max_ly_, max_lx_);
  const auto half = [](int n, int l) { return std::max(1, n >> l); };
  for (int ly = 0; ly <= max_ly_; ++ly) {
    if (ly > 0) {
      cv::Mat diag;
      const cv::Mat& prev = levels_[static_cast<size_t>(ly - 1)][0];
      cv::resize(prev, diag, cv::Size(half(width_, ly), half(height_, ly)), 0, 0, cv::INTER_AREA);
      levels_.push_back({diag});
    }
    auto& row = levels_[static_cast<size_t>(ly)];
    for (int lx = ly + 1; lx <= max_lx_; ++lx) {
      cv::Mat next;
      cv::resize(row.back(), next, cv::Size(half(width_, lx), half(height_, ly)), 0, 0,
                 cv::INTER_AREA);
      row.push_back(next);
    }
  }
}

const cv::Mat& EquirectSampler::level(int lx, int ly) const {
  ly = std::clamp(ly, 0, max_ly_);
  lx = std::clamp(std::max(lx, ly), 0, max_lx_);
  return levels_[static_cast<size_t>(ly)][static_cast<size_t>(lx - ly)];
}

Eigen::Vector3d EquirectSampler::row_lerp(const cv::Mat& img, int row, double x) const {
  const int w = img.cols;
  const double fl = std::floor(x);
  const double t = x - fl;
  // Wrap in double before converting: x may be far outside [0, w) after the pole shift.
  int c0 = 0, c1 = 0;
  if (options_.coverage_deg != 360) {  // VR180: clamp to the edge columns, never wrap
    c0 = static_cast<int>(std::clamp(fl, 0.0, static_cast<double>(w - 1)));
    c1 = static_cast<int>(std::clamp(fl + 1.0, 0.0, static_cast<double>(w - 1)));
  } else {
    c0 = static_cast<int>(fl - w * std::floor(fl / w));
    if (c0 >= w) c0 -= w;
    c1 = c0 + 1 == w ? 0 : c0 + 1;
  }
  const auto* p = img.ptr<cv::Vec3f>(row);
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) out[k] = (1.0 - t) * p[c0][k] + t * p[c1][k];
  return out;
}

Eigen::Vector3d EquirectSampler::sample_uv(double u, double v, int level_x, int level_y) const {
  const cv::Mat& img = level(level_x, level_y);
  const int w = img.cols, h = img.rows;
  const double x = u * w - 0.5;
  const double y = v * h - 0.5;
  const double fy = std::floor(y);
  const double t = y - fy;
  const int r0 = static_cast<int>(fy);
  const auto fetch_row = [&](int r) {
    if (r >= 0 && r < h) return row_lerp(img, r, x);
    if (options_.pole_rows == PoleRows::Clamp) return row_lerp(img, std::clamp(r, 0, h - 1), x);
    // Across the pole: row -1 - k is row k seen from the opposite azimuth.
    const int mirrored = r < 0 ? -1 - r : 2 * h - 1 - r;
    return row_lerp(img, std::clamp(mirrored, 0, h - 1), x + 0.5 * w);
  };
  if (t == 0.0) return fetch_row(r0);
  return (1.0 - t) * fetch_row(r0) + t * fetch_row(r0 + 1);
}

double EquirectSampler::image_u(double u) const {
  return 0.5 + (u - 0.5) * (360.0 / options_.coverage_deg);
}

double EquirectSampler::weight(double u) const {
  return coverage_weight({StereoMode::Mono, options_.coverage_deg}, (u - 0.5) * 360.0);
}

Eigen::Vector3d EquirectSampler::sample(const Eigen::Vector3d& dir) const {
  const Eigen::Vector2d uv = direction_to_uv(dir);
  const double w = weight(uv.x());
  if (w <= 0.0) return Eigen::Vector3d::Zero();
  return w * sample_uv(image_u(uv.x()), uv.y());
}

Eigen::Vector3d EquirectSampler::sample(const Eigen::Vector3d& dir,
                                        const Footprint& footprint) const {
  const Eigen::Vector2d duv = direction_to_uv(dir);
  const double w = weight(duv.x());
  if (w <= 0.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector2d uv(image_u(duv.x()), duv.y());
  if (options_.filter != SampleFilter::AreaAware) return w * sample_uv(uv.x(), uv.y());
  // Level l averages 2^l texels, so a footprint of n texels wants level log2(n).
  const auto lod = [](double texels, int max_level) {
    return std::clamp(std::log2(std::max(texels, 1.0)), 0.0, static_cast<double>(max_level));
  };
  const double ly_f = lod(footprint.dv_texels, max_ly_);
  const double lx_f = std::max(lod(footprint.du_texels, max_lx_), ly_f);
  const int lx0 = static_cast<int>(lx_f), ly0 = static_cast<int>(ly_f);
  const double tx = lx_f - lx0, ty = ly_f - ly0;
  const int lx1 = std::min(lx0 + 1, max_lx_), ly1 = std::min(ly0 + 1, max_ly_);
  const auto at = [&](int lx, int ly) { return sample_uv(uv.x(), uv.y(), lx, ly); };
  Eigen::Vector3d lo = at(lx0, ly0);
  if (tx > 0.0) lo = (1.0 - tx) * lo + tx * at(lx1, ly0);
  if (ty == 0.0) return w * lo;
  Eigen::Vector3d hi = at(lx0, ly1);
  if (tx > 0.0) hi = (1.0 - tx) * hi + tx * at(lx1, ly1);
  return w * ((1.0 - ty) * lo + ty * hi);
}

Footprint EquirectSampler::footprint(const Eigen::Vector3d& dir, const Eigen::Vector3d& dir_dx,
                                     const Eigen::Vector3d& dir_dy) const {
  const Eigen::Vector2d uv = direction_to_uv(dir);
  const auto delta = [&](const Eigen::Vector3d& other) {
    Eigen::Vector2d d = direction_to_uv(other) - uv;
    d.x() -= std::round(d.x());  // the short way round the seam
    return d;
  };
  const Eigen::Vector2d a = delta(dir_dx), b = delta(dir_dy);
  // A 180 image has its width over half the turn: twice the texels per degree.
  const double per_turn = width_ * (360.0 / options_.coverage_deg);
  return {std::max(std::abs(a.x()), std::abs(b.x())) * per_turn,
          std::max(std::abs(a.y()), std::abs(b.y())) * height_};
}

}  // namespace vdfx::effects
