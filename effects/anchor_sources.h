/// @file
/// @brief Anchors resolved against a sidecar's camera and tracks, for the sets that evaluate
/// effects (StackInterpolator, FlareSet, GrainSet, the editor's document): each effect's anchor
/// with its rotations (effects/anchor.h), effects with the same anchor sharing one AnchorFrames.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "effects/anchor.h"

namespace vdfx::effects {

/// What anchors are resolved against: a sidecar's camera and tracks, borrowed for the call that
/// resolves them (the AnchorFrames made own their rotations). The default has neither, so it
/// resolves the video anchor only: a set built without them from anchored effects throws.
struct AnchorSources {
  const CameraMotion* camera = nullptr;
  std::span<const SubjectTrack> tracks;
};

/// An anchor with its rotation at every frame (default: the video anchor, the identity).
struct ResolvedAnchor {
  Anchor anchor;
  AnchorFrames frames;
};

/// Resolves anchors, each once: effects with the same anchor get one AnchorFrames (shared
/// storage), so a set turns a direction once per anchor, not once per effect.
class AnchorResolver {
 public:
  explicit AnchorResolver(const AnchorSources& sources) : sources_(sources) {}
  /// anchor_frames(anchor, camera, tracks); throws std::invalid_argument as it does.
  ResolvedAnchor resolve(const Anchor& anchor);

 private:
  AnchorSources sources_;
  std::vector<ResolvedAnchor> seen_;
};

}  // namespace vdfx::effects
