/// @file
/// @brief grain_set_of: GrainSet construction with the sidecar's errors as input errors.
#include "app/grain_set_of.h"

#include <stdexcept>
#include <string>

#include "io/input_error.h"

namespace vdfx::app {

effects::GrainSet grain_set_of(const io::Sidecar& sidecar) {
  try {
    return effects::GrainSet(sidecar.grains, sidecar.interpolation, sidecar.video.fps);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string("sidecar grain cannot be interpolated: ") + e.what());
  }
}

}  // namespace vdfx::app
