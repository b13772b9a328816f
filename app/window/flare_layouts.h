/// @file
/// @brief This frame's flare layouts for a head pose: what FrameClient::flares answers for the
/// player and the editor.
#pragma once

#include <cstdint>
#include <vector>

#include "effects/flare_set.h"
#include "io/picture.h"
#include "xr/headset/pose.h"

namespace vdfx::app {

/// The layouts of every flare in `set` for a head pose (LOCAL) at `frame`: an auto light first
/// looks at `picture` (the video frame as decoded; converted to RGB on the CPU once per frame,
/// only for auto lights).
std::vector<effects::FlareLayout> flare_layouts(effects::FlareSet& set,
                                                const xr::Pose& head_in_local, std::int64_t frame,
                                                const io::Picture* picture);

}  // namespace vdfx::app
