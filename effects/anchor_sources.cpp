/// @file
/// @brief AnchorResolver: each anchor resolved once.
#include "effects/anchor_sources.h"

namespace vdfx::effects {

ResolvedAnchor AnchorResolver::resolve(const Anchor& anchor) {
  if (anchor.is_video()) return {};
  for (const ResolvedAnchor& r : seen_)
    if (r.anchor == anchor) return r;
  return seen_.emplace_back(
      ResolvedAnchor{anchor, anchor_frames(anchor, sources_.camera, sources_.tracks)});
}

}  // namespace vdfx::effects
