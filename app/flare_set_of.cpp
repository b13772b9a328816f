/// @file
/// @brief flare_set_of: FlareSet construction with the sidecar's errors as input errors.
#include "app/flare_set_of.h"

#include <stdexcept>
#include <string>

#include "io/input_error.h"

namespace vdfx::app {

effects::FlareSet flare_set_of(const io::Sidecar& sidecar) {
  try {
    return effects::FlareSet(sidecar.flares, sidecar.interpolation, sidecar.video.fps);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string("sidecar flares cannot be interpolated: ") + e.what());
  }
}

}  // namespace vdfx::app
