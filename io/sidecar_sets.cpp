/// @file
/// @brief FlareSet and GrainSet construction with the sidecar's errors as input errors.
#include "io/sidecar_sets.h"

#include <stdexcept>
#include <string>

#include "io/input_error.h"

namespace vdfx::io {

effects::FlareSet flare_set_of(const Sidecar& sidecar) {
  try {
    return effects::FlareSet(sidecar.flares, sidecar.interpolation, sidecar.video.fps);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("sidecar flares cannot be interpolated: ") + e.what());
  }
}

effects::GrainSet grain_set_of(const Sidecar& sidecar) {
  try {
    return effects::GrainSet(sidecar.grains, sidecar.interpolation, sidecar.video.fps);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("sidecar grain cannot be interpolated: ") + e.what());
  }
}

}  // namespace vdfx::io
