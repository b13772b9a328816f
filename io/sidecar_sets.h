/// @file
/// @brief The sidecar's flares and grain effects as the sets that lay them out per frame
/// (effects::FlareSet, effects::GrainSet), for every command and client that draws them (render,
/// play, edit, export, eval).
#pragma once

#include "effects/flare_set.h"
#include "effects/grain_layout.h"
#include "io/sidecar.h"

namespace vdfx::io {

/// Solves every flare's intensity keyframes. Throws InputError when they cannot be interpolated
/// (settings the reader would have rejected).
effects::FlareSet flare_set_of(const Sidecar& sidecar);

/// Solves every grain's intensity and size keyframes. Throws InputError when they cannot be
/// interpolated (settings the reader would have rejected).
effects::GrainSet grain_set_of(const Sidecar& sidecar);

}  // namespace vdfx::io
