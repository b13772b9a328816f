/// @file
/// @brief LightTrack: the windowed straight-line fit of the auto light's measurements.
#include "effects/light_track.h"

#include <Eigen/Geometry>
#include <cmath>
#include <iterator>
#include <numeric>
#include <vector>

#include "effects/coords.h"

namespace vdfx::effects {

namespace {

constexpr std::size_t kCacheFrames = 256;

}  // namespace

LightTrack::LightTrack(AutoLightOptions options) : options_(options) {}

void LightTrack::record(std::int64_t frame, const std::optional<Eigen::Vector3d>& measured) {
  latest_ = frame;
  if (cache_.count(frame)) return;
  cache_.emplace(frame, measured);
  while (cache_.size() > kCacheFrames) {
    // Forget the frame farthest from the one just shown (playback moves on, seeks jump).
    auto first = cache_.begin(), last = std::prev(cache_.end());
    cache_.erase(latest_ - first->first >= last->first - latest_ ? first : last);
  }
}

std::optional<Eigen::Vector3d> LightTrack::light(std::int64_t frame) const {
  const auto at = cache_.find(frame);
  if (at == cache_.end() || !at->second) return std::nullopt;
  const Eigen::Vector3d m = *at->second;
  // Tangent plane at f's measurement; gnomonic coordinates keep great circles straight.
  const Eigen::Vector3d helper =
      std::abs(m.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d e1 = helper.cross(m).normalized(), e2 = m.cross(e1);
  const double cos_jump = std::cos(options_.max_jump_deg * kDegToRad);
  std::vector<double> dk;
  std::vector<Eigen::Vector2d> p;
  for (auto it = cache_.lower_bound(frame - options_.window);
       it != cache_.end() && it->first <= frame; ++it) {
    if (!it->second) continue;
    const Eigen::Vector3d& v = *it->second;
    const double c = v.dot(m);
    if (c < cos_jump) continue;
    dk.push_back(static_cast<double>(it->first - frame));
    p.emplace_back(v.dot(e1) / c, v.dot(e2) / c);
  }
  if (p.size() < 2) return m;
  const double n = static_cast<double>(p.size());
  const double mk = std::accumulate(dk.begin(), dk.end(), 0.0) / n;
  Eigen::Vector2d mp = Eigen::Vector2d::Zero();
  for (const auto& q : p) mp += q / n;
  double sxx = 0.0;
  Eigen::Vector2d sxy = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    sxx += (dk[i] - mk) * (dk[i] - mk);
    sxy += (dk[i] - mk) * (p[i] - mp);
  }
  const Eigen::Vector2d slope = sxy / sxx;
  const Eigen::Vector2d at_f = mp - slope * mk;  // the line at dk = 0, i.e. at frame f
  return (m + at_f.x() * e1 + at_f.y() * e2).normalized();
}

}  // namespace vdfx::effects
