/// @file
/// @brief The flare scene `vdfx bench` and tests/bench/flare_gl_bench.cpp measure: a head at
/// 1.6 m looking 8 degrees away from a light, so the whole flare with its rings spreads over
/// the view.
#pragma once

#include "effects/flare_layout.h"
#include "xr/headset/session.h"

namespace vdfx::app::bench {

inline const effects::Direction kFlareLook{20.0, 5.0}, kFlareLight{27.0, 9.0};

/// The flare of `style` with `rings` rings for a head (app/bench/inputs.h head_at) looking at
/// kFlareLook and kFlareLight, intensity 1.
effects::FlareLayout flare_layout(effects::FlareStyle style, int rings);

}  // namespace vdfx::app::bench
