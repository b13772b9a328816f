/// @file
/// @brief The sidecar's frames of reference (contract: "Frames of reference"; docs/sidecar.md):
/// reading and writing `camera`, `tracks` and each entry's `anchor`, and the check that every
/// anchor names what it needs. Internal to io/ (the sidecar reader and writer call it).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "effects/anchor.h"
#include "io/sidecar.h"
#include "io/sidecar_checker.h"

namespace vdfx::io::detail {

/// An entry's optional "anchor" (absent: video).
void read_anchor(Checker& c, const json& entry, const std::string& ptr, effects::Anchor& out);
/// Writes "anchor" into an entry unless it is the video anchor (old readers see no change).
void write_anchor(nlohmann::ordered_json& entry, const effects::Anchor& anchor);

/// The document's "camera": one unit quaternion per frame (`frames`, when known).
void read_camera(Checker& c, const json& v, std::optional<std::int64_t> frames,
                 std::optional<effects::CameraMotion>& out);
/// The document's "tracks": unique valid names, contiguous strictly increasing frames inside
/// [0, frames), directions and confidences in range.
void read_tracks(Checker& c, const json& v, std::optional<std::int64_t> frames,
                 std::vector<effects::SubjectTrack>& out);
/// An entry's anchor and where it is ("/effects/3/anchor").
using AnchorAt = std::pair<std::string, effects::Anchor>;
/// Every entry's anchor names a camera or track the document has (reported at the anchor).
void check_anchors(Checker& c, const Sidecar& s, const std::vector<AnchorAt>& anchors);

nlohmann::ordered_json camera_to_json(const effects::CameraMotion& camera);
nlohmann::ordered_json tracks_to_json(const std::vector<effects::SubjectTrack>& tracks);

}  // namespace vdfx::io::detail
