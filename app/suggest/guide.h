/// @file
/// @brief Gaze guidance (docs/suggest.md, "Gaze guidance"; after Hartmann et al.'s Fig. 5b):
/// views that look away from the point of interest are desaturated and/or darkened, views
/// toward it are left neutral. With theta the angle between the view and the nearest point of
/// interest active at the frame, the guidance weight is
///   g = 0 (theta <= inner), smoothstep((theta - inner) / (outer - inner)), 1 (theta >= outer),
/// and the targets are saturation 1 - kGuideSaturationDepth * strength * g and exposure
/// -kGuideExposureStops * strength * g. At a frame no point of interest covers, g = 0.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "effects/anchor.h"
#include "effects/coords.h"

namespace vdfx::app::suggest {

inline constexpr double kGuideInnerDeg = 20.0;        //!< neutral within this angle of the point
inline constexpr double kGuideOuterDeg = 90.0;        //!< the full effect from this angle on
inline constexpr double kGuideSaturationDepth = 0.8;  //!< saturation 0.2 at strength 1
inline constexpr double kGuideExposureStops = 1.5;    //!< 1.5 stops darker at strength 1

struct PointOfInterest {
  effects::Direction direction;            //!< a track's: its direction at first_frame
  std::int64_t first_frame = 0;            //!< inclusive
  std::optional<std::int64_t> last_frame;  //!< inclusive; none: to the end
  /// "track:NAME": a subject track of the sidecar (resolve_track_points fills `path` and the
  /// frames from it); empty: a fixed direction. (Braced: points made as {direction, first,
  /// last} leave these as they are without a warning.)
  std::string track{};
  /// A track's direction at each frame from first_frame on (where the tracker did not see the
  /// subject, confidence 0, the last direction it did see; before any, the first it saw).
  std::vector<effects::Direction> path{};
  bool active_at(std::int64_t frame) const {
    return frame >= first_frame && (!last_frame || frame <= *last_frame);
  }
  /// Where the point is at `frame` (a track's nearest end outside its span).
  effects::Direction direction_at(std::int64_t frame) const;
};

/// "AZ,ALT", "AZ,ALT,FROM-TO" (frames, inclusive) or "track:NAME" (a subject track of the
/// sidecar, active over the frames it spans). Throws std::invalid_argument with a message naming
/// what is wrong.
PointOfInterest parse_point_of_interest(const std::string& text);

/// Each "track:NAME" point's path and frames from the sidecar's `tracks`. Throws
/// std::invalid_argument naming the option and `sidecar_name` when a name is none of them.
void resolve_track_points(std::vector<PointOfInterest>& points,
                          std::span<const effects::SubjectTrack> tracks,
                          const std::string& sidecar_name);

/// The guidance weight g at angle `theta_deg` from the point.
double guide_weight(double theta_deg);

/// g for the view `view` at `frame`: of the nearest active point; 0 when none is active.
double guide_weight_at(const std::vector<PointOfInterest>& points, const effects::Direction& view,
                       std::int64_t frame);

}  // namespace vdfx::app::suggest
