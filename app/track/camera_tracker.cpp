/// @file
/// @brief CameraTracker: key frames, optical flow, re-anchored fits, rotation averaging
/// (camera_tracker.h).
#include "app/track/camera_tracker.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>

#include "app/track/equirect_warp.h"
#include "app/track/rotation_fit.h"
#include "app/track/rotation_graph.h"
#include "effects/coords.h"

namespace vdfx::app::track {
namespace {

constexpr int kWindow = 15;           // Lucas-Kanade window, pixels
constexpr int kLevels = 3;            // pyramid levels above the image: follows ~80 px a frame
constexpr double kHeldWeight = 1e-3;  // a link that only says "the camera stayed put"
// A key frame match far off its prediction is a wrong one; after a loss (a cut, frames that
// could not be decoded) the prediction is only "the camera stayed put", so the match may correct
// it by as much as the flow's coarsest level reaches (a turn of about a fifth of the image width).
constexpr double kMaxMatchCorrectionDeg = 3.0;
constexpr double kMaxRestartCorrectionDeg = 20.0;

struct KeyFrame {
  std::int64_t frame = 0;
  cv::Mat grey;                                     //!< its analysis image
  std::vector<Eigen::Vector3d> dirs;                //!< its corners' directions (its video frame)
  Eigen::Matrix3d q = Eigen::Matrix3d::Identity();  //!< key frame -> world, so far
};

struct FrameFit {
  int key = -1;  //!< key frame measured against (-1: none, the previous orientation held)
  Eigen::Matrix3d relative = Eigen::Matrix3d::Identity();  //!< key frame's directions -> frame's
  int inliers = 0;
  bool held = false;
};

/// The weighted chordal mean of rotations, projected back onto SO(3).
Eigen::Matrix3d mean_rotation(const std::vector<std::pair<Eigen::Matrix3d, double>>& rs) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const auto& [r, w] : rs) m += w * r;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

}  // namespace

struct CameraTracker::Impl {
  CameraTrackOptions o;
  SphereGrid grid;
  int pad = 0;  //!< columns wrapped round the seam (and rows repeated) for the flow
  double threshold_rad = 0.0;
  std::vector<KeyFrame> keys;
  std::vector<RotationLink> links;
  std::vector<FrameFit> frames;
  bool tracking = false;            //!< a key frame's corners are being followed
  std::vector<cv::Mat> previous;    //!< pyramid of the last frame followed
  std::vector<cv::Point2f> points;  //!< corners there (padded OpenCV pixel coordinates)
  std::vector<int> feature;         //!< each one's index into keys.back().dirs
  std::size_t key_corners = 0;
  Eigen::Matrix3d last_q = Eigen::Matrix3d::Identity();

  explicit Impl(const CameraTrackOptions& options)
      : o(options), grid(SphereGrid::of_width(options.width, options.coverage_deg)) {
    pad = std::max(kWindow, grid.width / 10);
    threshold_rad = o.inlier_px * grid.degrees_per_pixel() * effects::kDegToRad;
  }

  // OpenCV's pixel coordinates put pixel centres at integers; the grid's at i + 0.5.
  Eigen::Vector3d unit_of_padded(const cv::Point2f& p) const {
    return grid.unit_at(
        {grid.wrap_x(p.x - static_cast<float>(pad) + 0.5f), p.y - static_cast<float>(pad) + 0.5f});
  }
  cv::Point2f padded_of(const Eigen::Vector3d& n) const {
    const cv::Point2f g = grid.pixel_of(n);
    return {g.x + static_cast<float>(pad) - 0.5f, g.y + static_cast<float>(pad) - 0.5f};
  }
  bool in_band(const Eigen::Vector3d& n) const {
    return std::abs(n.y()) <= std::sin(o.max_altitude_deg * effects::kDegToRad);
  }
  bool usable(const cv::Point2f& p) const {
    const cv::Point2f g(p.x - static_cast<float>(pad) + 0.5f, p.y - static_cast<float>(pad) + 0.5f);
    return grid.wraps() ? g.y >= 0 && g.y < grid.height && p.x >= 0 && p.x < grid.width + 2 * pad
                        : grid.inside(g);
  }

  std::vector<cv::Mat> pyramid(const cv::Mat& grey, int levels = kLevels) const {
    std::vector<cv::Mat> pyr;
    cv::buildOpticalFlowPyramid(pad_for_flow(grey, grid, pad), pyr, cv::Size(kWindow, kWindow),
                                levels);
    return pyr;
  }

  bool start_key(std::int64_t f, const cv::Mat& grey, const Eigen::Matrix3d& q);
  std::optional<RotationLink> match(int j, int n, const std::vector<cv::Mat>& pyr,
                                    bool restarting) const;
  int link_earlier(int n, const std::vector<cv::Mat>& pyr, bool restarting);
  void follow(std::int64_t f, const cv::Mat& grey, std::vector<cv::Mat> pyr);
  void restart(std::int64_t f, const cv::Mat& grey, const std::vector<cv::Mat>& pyr);
  CameraTrack finish();
};

bool CameraTracker::Impl::start_key(std::int64_t f, const cv::Mat& grey, const Eigen::Matrix3d& q) {
  cv::Mat mask = cv::Mat::zeros(grid.size(), CV_8U);
  const int band = static_cast<int>(std::floor(grid.height * (0.5 - o.max_altitude_deg / 180.0)));
  const int edge = grid.wraps() ? 0 : kWindow / 2;  // a half turn's side edges: no flow beyond
  mask(cv::Rect(edge, band, grid.width - 2 * edge, grid.height - 2 * band)).setTo(255);
  std::vector<cv::Point2f> corners;
  const double spacing =
      0.6 * std::sqrt(static_cast<double>(grid.width) * (grid.height - 2 * band) / o.points);
  cv::goodFeaturesToTrack(grey, corners, o.points, 0.01, std::max(3.0, spacing), mask, 5);
  if (corners.size() < 2 * static_cast<std::size_t>(kMinRotationPairs)) return false;
  KeyFrame key{f, grey.clone(), {}, q};
  points.clear();
  feature.clear();
  for (const cv::Point2f& c : corners) {
    key.dirs.push_back(grid.unit_at({c.x + 0.5f, c.y + 0.5f}));
    points.emplace_back(c.x + static_cast<float>(pad), c.y + static_cast<float>(pad));
    feature.push_back(static_cast<int>(feature.size()));
  }
  key_corners = corners.size();
  keys.push_back(std::move(key));
  tracking = true;
  return true;
}

/// Key frame j's corners found in key frame n: j's image turned by the predicted rotation, then
/// the flow of the small remainder.
std::optional<RotationLink> CameraTracker::Impl::match(int j, int n,
                                                       const std::vector<cv::Mat>& pyr,
                                                       bool restarting) const {
  const KeyFrame& a = keys[static_cast<std::size_t>(j)];
  if (a.grey.empty()) return std::nullopt;  // let go (link_earlier)
  const Eigen::Matrix3d predicted = keys[static_cast<std::size_t>(n)].q.transpose() * a.q;
  const int levels = restarting ? kLevels : 2;
  const std::vector<cv::Mat> warped = pyramid(warp_equirect(a.grey, grid, predicted), levels);
  std::vector<cv::Point2f> from, to;
  std::vector<Eigen::Vector3d> da, db;
  for (const Eigen::Vector3d& d : a.dirs) {
    const Eigen::Vector3d c = predicted * d;
    if (!in_band(c)) continue;
    from.push_back(padded_of(c));
    da.push_back(d);
  }
  if (from.size() < 3 * static_cast<std::size_t>(kMinRotationPairs)) return std::nullopt;
  std::vector<unsigned char> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(warped, pyr, from, to, status, error, cv::Size(kWindow, kWindow),
                           levels);
  std::vector<Eigen::Vector3d> ka, kb;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (status[i] && usable(to[i])) {
      ka.push_back(da[i]);
      kb.push_back(unit_of_padded(to[i]));
    }
  const RotationFit fit = fit_rotation(ka, kb, threshold_rad);
  const double correction_deg =
      rotation_angle(fit.rotation * predicted.transpose()) * effects::kRadToDeg;
  const int needed = std::max(3 * kMinRotationPairs, static_cast<int>(from.size() * 3 / 10));
  if (!fit.ok() || fit.inliers < needed ||
      correction_deg > (restarting ? kMaxRestartCorrectionDeg : kMaxMatchCorrectionDeg))
    return std::nullopt;
  return RotationLink{j, n, fit.rotation, static_cast<double>(fit.inliers)};
}

/// Links the new key frame n to earlier ones (2, 4, 8, ... back, and the first; after a loss the
/// previous one too) and moves its orientation to the weighted mean of what its links say.
/// Returns the links made.
int CameraTracker::Impl::link_earlier(int n, const std::vector<cv::Mat>& pyr, bool restarting) {
  std::vector<int> targets;
  if (restarting) targets.push_back(n - 1);
  for (int d = 2, k = 0; n - d >= 0 && k < o.far_links; d *= 2, ++k) targets.push_back(n - d);
  if (n >= 2 && o.far_links > 0 && targets.back() != 0) targets.push_back(0);
  std::vector<std::pair<Eigen::Matrix3d, double>> says;
  for (const RotationLink& l : links)
    if (l.to == n)
      says.emplace_back(keys[static_cast<std::size_t>(l.from)].q * l.rotation.transpose(),
                        l.weight);
  int made = 0;
  for (const int j : targets)
    if (const auto link = match(j, n, pyr, restarting)) {
      links.push_back(*link);
      says.emplace_back(keys[static_cast<std::size_t>(j)].q * link->rotation.transpose(),
                        link->weight);
      ++made;
    }
  if (!says.empty()) keys[static_cast<std::size_t>(n)].q = mean_rotation(says);
  // No later key frame links to one this far back (but the first): its picture can go, so an
  // hour of video holds a few hundred key frames' pictures, not thousands.
  const int oldest = n - (1 << std::min(o.far_links, 16));
  if (oldest > 0) {
    keys[static_cast<std::size_t>(oldest)].grey.release();
    keys[static_cast<std::size_t>(oldest)].dirs = {};
  }
  return made;
}

void CameraTracker::Impl::follow(std::int64_t f, const cv::Mat& grey, std::vector<cv::Mat> pyr) {
  std::vector<cv::Point2f> next;
  std::vector<unsigned char> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(previous, pyr, points, next, status, error, cv::Size(kWindow, kWindow),
                           kLevels);
  const KeyFrame& key = keys.back();
  std::vector<Eigen::Vector3d> a, b;
  std::vector<cv::Point2f> kept;
  std::vector<int> kept_feature;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!status[i] || !usable(next[i])) continue;
    const Eigen::Vector3d n = unit_of_padded(next[i]);
    if (!in_band(n)) continue;
    a.push_back(key.dirs[static_cast<std::size_t>(feature[i])]);
    b.push_back(n);
    // Back inside [pad, pad + width) after crossing the seam.
    kept.push_back(
        {grid.wrap_x(next[i].x - static_cast<float>(pad)) + static_cast<float>(pad), next[i].y});
    kept_feature.push_back(feature[i]);
  }
  const RotationFit fit = fit_rotation(a, b, threshold_rad);
  if (!fit.ok()) return restart(f, grey, pyr);
  points.clear();
  feature.clear();
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (fit.inlier[i]) {
      points.push_back(kept[i]);
      feature.push_back(kept_feature[i]);
    }
  const int k = static_cast<int>(keys.size()) - 1;
  last_q = key.q * fit.rotation.transpose();
  frames.push_back({k, fit.rotation, fit.inliers, false});
  const bool due = f - key.frame >= o.keyframe_spacing || points.size() < key_corners / 2;
  if (due && start_key(f, grey, last_q)) {
    links.push_back({k, k + 1, fit.rotation, static_cast<double>(fit.inliers)});
    link_earlier(k + 1, pyr, false);
    last_q = keys.back().q;
    frames.back() = {k + 1, Eigen::Matrix3d::Identity(), fit.inliers, false};
  }
  previous = std::move(pyr);
}

/// No rotation could be fitted (or nothing is followed yet): the orientation is held, and a new
/// key frame is tried here, tied to the last one only by "the camera stayed put" unless a match
/// with an earlier key frame says better.
void CameraTracker::Impl::restart(std::int64_t f, const cv::Mat& grey,
                                  const std::vector<cv::Mat>& pyr) {
  tracking = false;
  frames.push_back({-1, Eigen::Matrix3d::Identity(), 0, true});
  if (start_key(f, grey, last_q)) {
    const int n = static_cast<int>(keys.size()) - 1;
    int made = 0;
    if (n > 0) {
      links.push_back(
          {n - 1, n, last_q.transpose() * keys[static_cast<std::size_t>(n - 1)].q, kHeldWeight});
      made = link_earlier(n, pyr, true);
    }
    last_q = keys.back().q;
    // Held only when nothing but "the camera stayed put" ties it to the earlier key frames.
    frames.back() = {n, Eigen::Matrix3d::Identity(), 0, n > 0 && made == 0};
  }
  previous = pyr;
}

CameraTrack CameraTracker::Impl::finish() {
  CameraTrack out;
  std::vector<Eigen::Matrix3d> q;
  for (const KeyFrame& k : keys) q.push_back(k.q);
  out.worst_link_residual_deg = average_rotations(q, links) * effects::kRadToDeg;
  out.keyframes = static_cast<int>(keys.size());
  out.links = static_cast<int>(links.size());
  Eigen::Quaterniond last = Eigen::Quaterniond::Identity();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const FrameFit& fit = frames[f];
    Eigen::Quaterniond now = last;
    if (fit.key >= 0)
      now = Eigen::Quaterniond(q[static_cast<std::size_t>(fit.key)] * fit.relative.transpose());
    now.normalize();
    if (now.dot(last) < 0) now.coeffs() *= -1.0;  // the same rotation, continuous in sign
    out.orientation.push_back(now);
    out.inliers.push_back(fit.inliers);
    if (fit.held) out.held.push_back(static_cast<std::int64_t>(f));
    last = now;
  }
  return out;
}

CameraTracker::CameraTracker(const CameraTrackOptions& options)
    : impl_(std::make_unique<Impl>(options)) {}
CameraTracker::~CameraTracker() = default;

const SphereGrid& CameraTracker::grid() const {
  return impl_->grid;
}

void CameraTracker::add(const cv::Mat& grey) {
  Impl& m = *impl_;
  const auto f = static_cast<std::int64_t>(m.frames.size());
  if (grey.empty()) {
    m.frames.push_back({-1, Eigen::Matrix3d::Identity(), 0, true});
    return;
  }
  std::vector<cv::Mat> pyr = m.pyramid(grey);
  if (m.tracking)
    m.follow(f, grey, std::move(pyr));
  else
    m.restart(f, grey, pyr);
}

CameraTrack CameraTracker::finish() {
  return impl_->finish();
}

}  // namespace vdfx::app::track
