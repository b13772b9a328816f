/// @file
/// @brief `--stabilize` for the player and the headset (docs/player.md, "Stabilised"): the view
/// shows the world frame, so each head or eye pose is turned into the video frame it samples
/// (contract: the picture's direction w shows the video at q_f^-1 w q_f) before the view's rays,
/// its parameters, flares and grain are computed: the effects are evaluated at the video direction
/// the view shows, as unstabilised.
#pragma once

#include <cstdint>

#include "effects/anchor.h"
#include "xr/headset/pose.h"

namespace vdfx::app {

/// `pose` (LOCAL, the world frame) composed with q_f^-1 at video frame `frame` of `world`
/// (effects::AnchorFrames::world of the sidecar's camera): a ray r of the pose becomes q_f^-1 r
/// q_f. The identity frames return `pose` as it is.
xr::Pose video_frame_pose(const xr::Pose& pose, const effects::AnchorFrames& world,
                          std::int64_t frame);

}  // namespace vdfx::app
