/// @file
/// @brief The sidecar's effects as the objects that evaluate them: the stack's interpolation
/// (effects::StackInterpolator), the flares and grain effects as the sets that lay them out per
/// frame (effects::FlareSet, effects::GrainSet), each effect turned by its anchor (the sidecar's
/// camera and tracks), for every command and client that draws or prints them (render, play,
/// edit, export, eval, publish, bench).
#pragma once

#include "effects/anchor_sources.h"
#include "effects/flare_set.h"
#include "effects/grain_layout.h"
#include "effects/stack_interpolator.h"
#include "io/sidecar.h"

namespace vdfx::io {

/// What the sidecar's anchors are resolved against: its camera and tracks (borrowed from
/// `sidecar`, which must outlive the sets built with them).
effects::AnchorSources anchor_sources(const Sidecar& sidecar);

/// Solves every stack effect's keyframes, each with its anchor. Throws InputError when they
/// cannot be interpolated (settings, or anchors, that the reader would have rejected).
effects::StackInterpolator stack_of(const Sidecar& sidecar);

/// Solves every flare's intensity keyframes, each with its anchor. Throws InputError when they
/// cannot be interpolated (settings, or anchors, that the reader would have rejected).
effects::FlareSet flare_set_of(const Sidecar& sidecar);

/// Solves every grain's intensity and size keyframes, each with its anchor. Throws InputError
/// when they cannot be interpolated (settings, or anchors, that the reader would have rejected).
effects::GrainSet grain_set_of(const Sidecar& sidecar);

}  // namespace vdfx::io
