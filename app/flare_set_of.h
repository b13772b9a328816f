/// @file
/// @brief The sidecar's flares, ready to lay out per frame (effects::FlareSet), for the commands
/// and clients that draw them (render, play, eval).
#pragma once

#include "effects/flare_set.h"
#include "io/picture.h"
#include "io/sidecar.h"
#include "xr/pose.h"

namespace vdfx::app {

/// Solves every flare's intensity keyframes. Throws io::InputError when they cannot be
/// interpolated (settings the reader would have rejected).
effects::FlareSet flare_set_of(const io::Sidecar& sidecar);

/// This frame's flare layouts for a head pose (LOCAL): an auto light first looks at `picture`
/// (the video frame as decoded; converted to RGB on the CPU once per frame, only for auto
/// lights). What FrameClient::flares answers for the player and the editor.
std::vector<effects::FlareLayout> flare_layouts(effects::FlareSet& set,
                                                const xr::Pose& head_in_local, std::int64_t frame,
                                                const io::Picture* picture);

}  // namespace vdfx::app
