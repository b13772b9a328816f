/// @file
/// @brief The sidecar's grain effects, ready to lay out per frame (effects::GrainSet), for the
/// commands and clients that draw them (render, play, eval).
#pragma once

#include "effects/grain_layout.h"
#include "io/sidecar.h"

namespace vdfx::app {

/// Solves every grain's intensity and size keyframes. Throws io::InputError when they cannot be
/// interpolated (settings the reader would have rejected).
effects::GrainSet grain_set_of(const io::Sidecar& sidecar);

}  // namespace vdfx::app
