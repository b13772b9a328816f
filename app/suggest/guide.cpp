/// @file
/// @brief The gaze-guidance field (guide.h).
#include "app/suggest/guide.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vdfx::app::suggest {

namespace {

double number(const std::string& text, const std::string& whole, const char* what) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw std::invalid_argument("--poi " + whole + ": " + what + " '" + text + "' is not a number");
  return v;
}

}  // namespace

PointOfInterest parse_point_of_interest(const std::string& text) {
  if (text.rfind("track:", 0) == 0) {
    PointOfInterest p;
    p.track = text.substr(6);
    if (!effects::valid_track_name(p.track))
      throw std::invalid_argument("--poi " + text +
                                  ": a track's name is 1 to 64 of A-Z, a-z, 0-9, _ and -");
    return p;
  }
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    parts.push_back(text.substr(start, comma - start));
  parts.push_back(text.substr(start));
  if (parts.size() != 2 && parts.size() != 3)
    throw std::invalid_argument("--poi " + text + ": expected AZ,ALT or AZ,ALT,FROM-TO");
  PointOfInterest p;
  const double az = number(parts[0], text, "azimuth");
  const double alt = number(parts[1], text, "altitude");
  if (alt < -90.0 || alt > 90.0)
    throw std::invalid_argument("--poi " + text + ": altitude must be within [-90, 90]");
  p.direction = {effects::wrap_azimuth_deg(az), alt};
  if (parts.size() == 3) {
    const auto dash = parts[2].find('-', 1);
    if (dash == std::string::npos)
      throw std::invalid_argument("--poi " + text + ": frames must be FROM-TO");
    const double from = number(parts[2].substr(0, dash), text, "first frame");
    const double to = number(parts[2].substr(dash + 1), text, "last frame");
    if (from < 0 || to < from || from != std::floor(from) || to != std::floor(to))
      throw std::invalid_argument("--poi " + text +
                                  ": frames must be whole, FROM >= 0 and TO >= FROM");
    p.first_frame = static_cast<std::int64_t>(from);
    p.last_frame = static_cast<std::int64_t>(to);
  }
  return p;
}

effects::Direction PointOfInterest::direction_at(std::int64_t frame) const {
  if (path.empty()) return direction;
  const std::int64_t i =
      std::clamp<std::int64_t>(frame - first_frame, 0, static_cast<std::int64_t>(path.size()) - 1);
  return path[static_cast<std::size_t>(i)];
}

void resolve_track_points(std::vector<PointOfInterest>& points,
                          std::span<const effects::SubjectTrack> tracks,
                          const std::string& sidecar_name) {
  for (PointOfInterest& p : points) {
    if (p.track.empty()) continue;
    const auto t = std::find_if(tracks.begin(), tracks.end(),
                                [&](const effects::SubjectTrack& s) { return s.name == p.track; });
    if (t == tracks.end() || t->points.empty()) {
      std::string names;
      for (const effects::SubjectTrack& s : tracks) names += (names.empty() ? "" : ", ") + s.name;
      throw std::invalid_argument(
          "--poi track:" + p.track + ": " + sidecar_name + " has no track '" + p.track + "' (" +
          (names.empty() ? "it has none: run vdfx track subject" : "it has: " + names) + ")");
    }
    // Frames the tracker did not see the subject at keep the direction last seen (before the
    // first sighting: the first), whatever the track stores there.
    const auto seen = std::find_if(t->points.begin(), t->points.end(),
                                   [](const effects::TrackPoint& q) { return q.confidence > 0.0; });
    effects::Direction held = (seen == t->points.end() ? t->points.front() : *seen).direction;
    p.path.clear();
    for (const effects::TrackPoint& q : t->points) {
      if (q.confidence > 0.0) held = q.direction;
      p.path.push_back(held);
    }
    p.first_frame = t->points.front().frame;
    p.last_frame = t->points.back().frame;
    p.direction = p.path.front();
  }
}

double guide_weight(double theta_deg) {
  const double x =
      std::clamp((theta_deg - kGuideInnerDeg) / (kGuideOuterDeg - kGuideInnerDeg), 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

double guide_weight_at(const std::vector<PointOfInterest>& points, const effects::Direction& view,
                       std::int64_t frame) {
  double nearest = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d v = effects::to_unit(view);
  for (const auto& p : points)
    if (p.active_at(frame))
      nearest =
          std::min(nearest, effects::angle_between(v, effects::to_unit(p.direction_at(frame))) *
                                effects::kRadToDeg);
  return std::isinf(nearest) ? 0.0 : guide_weight(nearest);
}

}  // namespace vdfx::app::suggest
