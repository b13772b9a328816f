/// @file
/// @brief Anchors: names, the camera's and a track's rotation at every frame.
#include "effects/anchor.h"

#include <algorithm>
#include <stdexcept>

namespace vdfx::effects {

namespace {

constexpr std::string_view kTrackPrefix = "track:";

}  // namespace

std::string anchor_name(const Anchor& anchor) {
  switch (anchor.kind) {
    case Anchor::Kind::World: return "world";
    case Anchor::Kind::Track: return std::string(kTrackPrefix) + anchor.track;
    case Anchor::Kind::Video: break;
  }
  return "video";
}

std::optional<Anchor> parse_anchor(std::string_view text) {
  if (text == "video") return Anchor{};
  if (text == "world") return Anchor{Anchor::Kind::World, {}};
  if (text.starts_with(kTrackPrefix)) {
    const std::string_view name = text.substr(kTrackPrefix.size());
    if (valid_track_name(name)) return Anchor{Anchor::Kind::Track, std::string(name)};
  }
  return std::nullopt;
}

bool valid_track_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxTrackNameLength) return false;
  return std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '_' || ch == '-';
  });
}

Eigen::Quaterniond to_eigen(const Quat& q) {
  return {q[0], q[1], q[2], q[3]};
}

Quat from_eigen(const Eigen::Quaterniond& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

const char* camera_source_name(CameraMotion::Source source) {
  switch (source) {
    case CameraMotion::Source::Camm: return "camm";
    case CameraMotion::Source::Given: return "given";
    case CameraMotion::Source::Estimated: break;
  }
  return "estimated";
}

std::optional<CameraMotion::Source> parse_camera_source(std::string_view text) {
  for (const auto s :
       {CameraMotion::Source::Estimated, CameraMotion::Source::Camm, CameraMotion::Source::Given})
    if (text == camera_source_name(s)) return s;
  return std::nullopt;
}

AnchorFrames AnchorFrames::world(const CameraMotion& camera) {
  auto rotations = std::make_shared<std::vector<Eigen::Matrix3d>>();
  rotations->reserve(camera.orientation.size());
  for (const Quat& q : camera.orientation)
    rotations->push_back(to_eigen(q).normalized().toRotationMatrix());
  if (rotations->empty()) return {};
  return {std::move(rotations), 0};
}

AnchorFrames AnchorFrames::track(const SubjectTrack& track) {
  if (track.points.empty()) return {};
  const Eigen::Vector3d first = to_unit(track.points.front().direction);
  auto rotations = std::make_shared<std::vector<Eigen::Matrix3d>>();
  rotations->reserve(track.points.size());
  for (const TrackPoint& p : track.points)
    rotations->push_back(
        Eigen::Quaterniond::FromTwoVectors(to_unit(p.direction), first).toRotationMatrix());
  return {std::move(rotations), track.points.front().frame};
}

Eigen::Matrix3d AnchorFrames::at(std::int64_t frame) const {
  if (!rotations_) return Eigen::Matrix3d::Identity();
  return stored(frame);
}

Eigen::Vector3d AnchorFrames::unapply(const Eigen::Vector3d& unit, std::int64_t frame) const {
  if (!rotations_) return unit;
  return stored(frame).transpose() * unit;
}

Direction AnchorFrames::apply(const Direction& d, std::int64_t frame) const {
  if (!rotations_) return d;
  return from_unit(apply(to_unit(d), frame));
}

Direction AnchorFrames::unapply(const Direction& d, std::int64_t frame) const {
  if (!rotations_) return d;
  return from_unit(unapply(to_unit(d), frame));
}

AnchorFrames anchor_frames(const Anchor& anchor, const CameraMotion* camera,
                           std::span<const SubjectTrack> tracks) {
  switch (anchor.kind) {
    case Anchor::Kind::Video: return {};
    case Anchor::Kind::World:
      if (!camera)
        throw std::invalid_argument(
            "anchor \"world\" needs the camera's orientation (the sidecar's camera section: "
            "vdfx track camera)");
      return AnchorFrames::world(*camera);
    case Anchor::Kind::Track: break;
  }
  for (const SubjectTrack& t : tracks)
    if (t.name == anchor.track) return AnchorFrames::track(t);
  throw std::invalid_argument("anchor \"" + anchor_name(anchor) + "\" names no track (the " +
                              "sidecar's tracks: vdfx track subject --name " + anchor.track + ")");
}

}  // namespace vdfx::effects
