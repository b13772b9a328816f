/// @file
/// @brief InputState <-> recording sample (io/recording.h), the one place they are converted.
#pragma once

#include "io/recording.h"
#include "xr/input/actions.h"

namespace vdfx::xr {

/// Head always; a hand only when tracked (the file omits untracked hands). Grip is not stored:
/// the vdfx backends keep grip equal to aim.
io::RecordedSample to_recorded_sample(const InputState& state);

/// Head tracked; hands tracked when present; grip = aim.
InputState from_recorded_sample(const io::RecordedSample& sample);

}  // namespace vdfx::xr
