/// @file
/// @brief EquirectSampler: bilinear and footprint-filtered sampling of equirect images.
#include "effects/equirect_sampler.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "effects/coords.h"
#include "effects/mip_chain.h"
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
  if (!(options_.max_anisotropy >= 1.0))
    throw std::invalid_argument("EquirectSampler: max_anisotropy must be at least 1");
  if (options_.filter == SampleFilter::Footprint)
    levels_ = build_mip_chain(equirect);
  else
    levels_ = {equirect};
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

Eigen::Vector3d EquirectSampler::sample_uv(double u, double v, int level) const {
  const cv::Mat& img = levels_[static_cast<std::size_t>(std::clamp(level, 0, levels() - 1))];
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

Eigen::Vector3d EquirectSampler::sample_lod(double u, double v, double lod) const {
  const int last = levels() - 1;
  if (!(lod > 0.0)) return sample_uv(u, v, 0);
  if (lod >= last) return sample_uv(u, v, last);
  const int l0 = static_cast<int>(lod);
  const double f = lod - l0;
  const Eigen::Vector3d lo = sample_uv(u, v, l0);
  return f == 0.0 ? lo : Eigen::Vector3d((1.0 - f) * lo + f * sample_uv(u, v, l0 + 1));
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

Eigen::Vector3d EquirectSampler::sample_pixel(const ViewCamera& camera, double x, double y) const {
  const Eigen::Vector3d centre = camera.ray(x, y);
  const double w = weight(direction_to_uv(centre).x());
  if (w <= 0.0) return Eigen::Vector3d::Zero();
  if (options_.filter == SampleFilter::Bilinear) return w * sample(centre);
  return w * footprint_sample(camera, x, y);
}

Eigen::Vector3d EquirectSampler::footprint_sample(const ViewCamera& camera, double x,
                                                  double y) const {
  // The unnormalised ray is affine in the pixel position: d + dx ex + dy ey.
  const Eigen::Matrix3d& rot = camera.camera_to_world();
  const Eigen::Vector2d t = camera.tangent(x, y);
  const Eigen::Vector3d d = rot * Eigen::Vector3d(t.x(), t.y(), -1.0);
  const Eigen::Vector3d ex = rot.col(0) / camera.fx(), ey = -rot.col(1) / camera.fy();
  const double per_turn = width_ * (360.0 / options_.coverage_deg);
  const FootprintTaps taps =
      footprint_taps(equirect_jacobian(d, ex, ey, {per_turn, static_cast<double>(height_)}),
                     options_.max_anisotropy, per_turn);
  const Eigen::Vector3d step = taps.spacing * (taps.axis.x() * ex + taps.axis.y() * ey);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = -taps.half_count; k <= taps.half_count; ++k) {
    const Eigen::Vector2d uv = direction_to_uv(d + k * step);
    sum += taps.weight(k) * sample_lod(image_u(uv.x()), uv.y(), taps.lod);
  }
  return sum;
}

}  // namespace vdfx::effects
