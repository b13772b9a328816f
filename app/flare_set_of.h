/// @file
/// @brief The sidecar's flares, ready to lay out per frame (effects::FlareSet), for the commands
/// and clients that draw them (render, play, eval).
#pragma once

#include "effects/flare_set.h"
#include "io/sidecar.h"

namespace vdfx::app {

/// Solves every flare's intensity keyframes. Throws io::InputError when they cannot be
/// interpolated (settings the reader would have rejected).
effects::FlareSet flare_set_of(const io::Sidecar& sidecar);

}  // namespace vdfx::app
