/// @file
/// @brief The backstop against non-finite effect parameters: render and eval refuse to draw or
/// print NaN or infinity (docs/reliability.md, class 4). No GL or media library, so the light
/// `eval` command can use it.
#pragma once

#include <cstdint>
#include <string>

#include "effects/coords.h"
#include "effects/effect_types.h"

namespace vdfx::app {

/// Throws io::InputError naming `sidecar_name` and the view when an evaluated parameter is NaN
/// or infinite: the validator keeps the interpolation finite (docs/sidecar.md), and this is the
/// backstop that refuses to render or print such values instead of a black image or "null".
void require_finite(const effects::StackParams& params, const std::string& sidecar_name,
                    const effects::Direction& at, std::int64_t frame);

}  // namespace vdfx::app
