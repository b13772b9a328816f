/// @file
/// @brief The grain scene `vdfx bench` and tests/bench/grain_gl_bench.cpp measure: one grain
/// effect of a style (seed 7, size 1, constant intensity) seen by the flare scene's head
/// (app/bench/flare_setup.h), so both layers are timed on the same eye of the play frame.
#pragma once

#include "effects/grain_layout.h"

namespace vdfx::app::bench {

/// One grain effect of `style` at `intensity` (one keyframe, size 1) with the style's default
/// settings (effects::GrainSettings(style)) but `count` particles when count > 0 and a sphere of
/// `sphere_m` when above 0 (object_cloud), at 30 fps.
effects::GrainSet grain_set(effects::GrainStyle style, double intensity, int count = 0,
                            double sphere_m = 0.0);

/// The head of the flare scene (head_at(kFlareLook)) as the grain layout takes it.
effects::HeadPose grain_head();

}  // namespace vdfx::app::bench
