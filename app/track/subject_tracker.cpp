/// @file
/// @brief SubjectTracker: template matching on views re-centred on the subject
/// (subject_tracker.h).
#include "app/track/subject_tracker.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"

namespace vdfx::app::track {
namespace {

constexpr int kSizes = 4;  // template sizes kept: step^-4 .. step^4 times the start's

effects::EquirectSampler sampler_of(const cv::Mat& equirect, int coverage_deg) {
  effects::SamplerOptions s;
  s.filter = effects::SampleFilter::Footprint;
  s.pole_rows = effects::PoleRows::AcrossPole;  // a half turn clamps it itself
  s.coverage_deg = coverage_deg;
  return effects::EquirectSampler(equirect, s);
}

effects::ViewCamera camera_of(const Eigen::Matrix3d& axes, double focal, int side) {
  return effects::ViewCamera(axes, focal, focal, 0.5 * side, 0.5 * side, side, side);
}

/// The peak's offset from the middle sample: the vertex of the parabola through three samples.
double parabola_peak(double left, double centre, double right) {
  const double curve = left - 2.0 * centre + right;
  return curve < 0.0 ? std::clamp(0.5 * (left - right) / curve, -0.5, 0.5) : 0.0;
}

/// The sub-pixel position of the maximum at `at` of a correlation map.
cv::Point2d refine_peak(const cv::Mat& map, cv::Point at) {
  cv::Point2d p(at.x, at.y);
  const auto v = [&map](int x, int y) { return static_cast<double>(map.at<float>(y, x)); };
  if (at.x > 0 && at.x + 1 < map.cols)
    p.x += parabola_peak(v(at.x - 1, at.y), v(at.x, at.y), v(at.x + 1, at.y));
  if (at.y > 0 && at.y + 1 < map.rows)
    p.y += parabola_peak(v(at.x, at.y - 1), v(at.x, at.y), v(at.x, at.y + 1));
  return p;
}

}  // namespace

int SubjectTracker::equirect_width(const SubjectOptions& options) {
  const int w = static_cast<int>(std::lround(360.0 * options.template_px / options.size_deg));
  return std::clamp(w, 128, 8192) / 2 * 2;
}

SubjectTracker::SubjectTracker(const cv::Mat& equirect, const Eigen::Vector3d& at,
                               const SubjectOptions& options)
    : o_(options), last_(at.normalized()) {
  focal_ = 0.5 * o_.template_px / std::tan(0.5 * o_.size_deg * effects::kDegToRad);
  axes_ = effects::pose_rotation({effects::from_unit(last_), 0.0});
  const cv::Mat view = effects::sample_view(sampler_of(equirect, o_.coverage_deg),
                                            camera_of(axes_, focal_, o_.template_px));
  // The template at each size tried (one search view a frame, matched at several sizes).
  templates_ = sizes_of(view);
  renewed_ = templates_;
}

std::vector<cv::Mat> SubjectTracker::sizes_of(const cv::Mat& view) const {
  std::vector<cv::Mat> out;
  for (int k = -kSizes; k <= kSizes; ++k) {
    const int side = static_cast<int>(std::lround(o_.template_px * std::pow(o_.scale_step, k)));
    cv::Mat t;
    cv::resize(view, t, cv::Size(side, side), 0, 0, k < 0 ? cv::INTER_AREA : cv::INTER_LINEAR);
    out.push_back(t);
  }
  return out;
}

void SubjectTracker::renew(const effects::EquirectSampler& sampler) {
  renewed_ =
      sizes_of(effects::sample_view(sampler, camera_of(axes_, focal_ / scale_, o_.template_px)));
}

SubjectSample SubjectTracker::start() const {
  return {last_, 1.0, o_.size_deg, true};
}

SubjectTracker::SearchView SubjectTracker::search_view(const effects::EquirectSampler& sampler,
                                                       double side_widths) const {
  const int side = std::max(o_.template_px + 2,
                            static_cast<int>(std::lround(o_.template_px * side_widths)) / 2 * 2);
  const Eigen::Vector3d predicted = lost_ ? last_ : (velocity_ * last_).normalized();
  const Eigen::Matrix3d axes = Eigen::Quaterniond::FromTwoVectors(last_, predicted) * axes_;
  const effects::ViewCamera camera = camera_of(axes, focal_ / scale_, side);
  return {camera, effects::sample_view(sampler, camera)};
}

SubjectTracker::Match SubjectTracker::search(const SearchView& v,
                                             const std::vector<cv::Mat>& templates) const {
  // The view is at the last size; the template at the sizes around it: a step either way, or
  // while lost (the subject may have changed more) two and four steps either way.
  const std::vector<int> sizes =
      lost_ ? std::vector<int>{-4, -2, 0, 2, 4} : std::vector<int>{-1, 0, 1};
  Match best;
  for (const int k : sizes) {
    const cv::Mat& t = templates[static_cast<std::size_t>(k + kSizes)];
    if (t.cols >= v.view.cols) continue;
    cv::Mat map;
    cv::matchTemplate(v.view, t, map, cv::TM_CCOEFF_NORMED);
    double score = 0.0;
    cv::Point at;
    cv::minMaxLoc(map, nullptr, &score, nullptr, &at);
    if (!(score > best.score)) continue;
    // matchTemplate's (x, y) puts the template's top-left corner on pixel (x, y): its centre is
    // half its side further, in pixel-edge coordinates.
    const cv::Point2d p = refine_peak(map, at);
    best = {score, v.camera.ray(p.x + 0.5 * t.cols, p.y + 0.5 * t.rows),
            scale_ * t.cols / static_cast<double>(o_.template_px)};
  }
  return best;
}

SubjectSample SubjectTracker::step(const cv::Mat& equirect) {
  const effects::EquirectSampler sampler = sampler_of(equirect, o_.coverage_deg);
  const SearchView v = search_view(sampler, lost_ ? 2.0 * o_.search : o_.search);
  const double bar = lost_ ? o_.found_score : o_.lost_score;
  // The start's template wherever it matches; else the renewed one, above its own bar.
  Match m = search(v, templates_);
  if (m.score < bar) {
    m = search(v, renewed_);
    if (m.score < std::max(bar, o_.renew_score)) {
      lost_ = true;
      velocity_ = Eigen::Quaterniond::Identity();
      return {last_, 0.0, o_.size_deg * scale_, false};
    }
  }
  const Eigen::Quaterniond moved = Eigen::Quaterniond::FromTwoVectors(last_, m.direction);
  velocity_ = lost_ ? Eigen::Quaterniond::Identity() : moved;
  axes_ = moved * axes_;
  last_ = m.direction;
  scale_ = m.scale;
  lost_ = false;
  renew(sampler);
  return {last_, std::min(1.0, m.score), o_.size_deg * scale_, true};
}

}  // namespace vdfx::app::track
