/// @file
/// @brief Frames of reference (contract: "Frames of reference"; docs/anchors.md): an effect's
/// anchor, the sidecar's camera orientation and subject tracks, and the one rotation per frame an
/// anchor applies to a view direction (per pixel: to each pixel's direction) before the effect's
/// keyframes are interpolated. The solve never sees the anchor: keyframe directions are stored in
/// the anchor's frame, so every keyframe is reproduced there exactly as before.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "effects/coords.h"

namespace vdfx::effects {

/// What an effect's keyframe directions are fixed to.
struct Anchor {
  enum class Kind { Video, World, Track };
  Kind kind = Kind::Video;  //!< Video: directions of the video frame (the default)
  std::string track;        //!< Kind::Track: the subject track's name
  bool operator==(const Anchor&) const = default;
  bool is_video() const { return kind == Kind::Video; }
};

/// "video", "world" or "track:NAME", as the sidecar writes it.
std::string anchor_name(const Anchor& anchor);
/// The anchor `text` names, or nothing when it is none of the three forms (or the track name is
/// not a valid one).
std::optional<Anchor> parse_anchor(std::string_view text);

/// A unit quaternion [w, x, y, z], as the sidecar writes it.
using Quat = std::array<double, 4>;
Eigen::Quaterniond to_eigen(const Quat& q);
Quat from_eigen(const Eigen::Quaterniond& q);

/// The sidecar's "camera": the camera's orientation at every video frame. orientation[f] = q_f
/// takes a direction of the video frame at frame f into the world: n_world = q_f n q_f^-1.
struct CameraMotion {
  enum class Source { Estimated, Camm, Given };
  Source source = Source::Estimated;
  std::vector<Quat> orientation;  //!< one per video frame
  bool operator==(const CameraMotion&) const = default;
};
/// "estimated", "camm", "given".
const char* camera_source_name(CameraMotion::Source source);
std::optional<CameraMotion::Source> parse_camera_source(std::string_view text);

/// One frame of a subject track: where the subject is (a direction of the video frame) and how
/// sure the tracker was (0: not seen there, the direction is the last one held).
struct TrackPoint {
  std::int64_t frame = 0;
  Direction direction;
  double confidence = 1.0;  //!< [0, 1]
  bool operator==(const TrackPoint&) const = default;
};

/// A sidecar "tracks" entry: one point per frame over a contiguous span of frames.
struct SubjectTrack {
  std::string name;  //!< [A-Za-z0-9_-]{1,64}, unique in the sidecar
  std::vector<TrackPoint> points;
  bool operator==(const SubjectTrack&) const = default;
};

/// The longest track name.
inline constexpr std::size_t kMaxTrackNameLength = 64;
/// Whether `name` may name a track: [A-Za-z0-9_-]{1,64}.
bool valid_track_name(std::string_view name);

/// The rotation an anchor applies at every frame: immutable, cheap to copy (shared storage),
/// safe to read from any thread. A default-constructed one is the video anchor: the identity,
/// which costs nothing (apply() returns its argument).
class AnchorFrames {
 public:
  AnchorFrames() = default;
  /// The world anchor: q_f as a rotation matrix at each frame of `camera`.
  static AnchorFrames world(const CameraMotion& camera);
  /// A track anchor: the shortest-arc rotation taking the track's direction at f to its
  /// direction at its first frame (before the span: the identity; after it: the last point's).
  static AnchorFrames track(const SubjectTrack& track);

  bool identity() const { return rotations_ == nullptr; }
  /// The rotation at `frame` (frames outside the stored span take the nearest end's).
  Eigen::Matrix3d at(std::int64_t frame) const;
  /// `unit` (a direction of the video frame at `frame`) in the anchor's frame. Inline: it runs
  /// once per evaluation (per pixel in the per-pixel grid), a 3 x 3 product of a stored matrix.
  Eigen::Vector3d apply(const Eigen::Vector3d& unit, std::int64_t frame) const {
    return rotations_ ? Eigen::Vector3d(stored(frame) * unit) : unit;
  }
  /// The inverse: a direction of the anchor's frame as the video frame shows it at `frame`.
  Eigen::Vector3d unapply(const Eigen::Vector3d& unit, std::int64_t frame) const;
  Direction apply(const Direction& d, std::int64_t frame) const;
  Direction unapply(const Direction& d, std::int64_t frame) const;

 private:
  AnchorFrames(std::shared_ptr<const std::vector<Eigen::Matrix3d>> rotations, std::int64_t first)
      : rotations_(std::move(rotations)), first_(first) {}
  /// The stored rotation at `frame`, the nearest end's outside the span (rotations_ set).
  const Eigen::Matrix3d& stored(std::int64_t frame) const {
    const auto last = static_cast<std::int64_t>(rotations_->size()) - 1;
    return (
        *rotations_)[static_cast<std::size_t>(std::clamp<std::int64_t>(frame - first_, 0, last))];
  }
  std::shared_ptr<const std::vector<Eigen::Matrix3d>> rotations_;
  std::int64_t first_ = 0;  //!< the frame of rotations_[0]
};

/// The frames `anchor` names, from a sidecar's camera and tracks. Throws std::invalid_argument
/// naming what is missing when the anchor is "world" without a camera or names no track.
AnchorFrames anchor_frames(const Anchor& anchor, const CameraMotion* camera,
                           std::span<const SubjectTrack> tracks);

}  // namespace vdfx::effects
