/// @file
/// @brief flare_set_of: FlareSet construction with the sidecar's errors as input errors.
#include "app/flare_set_of.h"

#include <stdexcept>
#include <string>

#include "io/input_error.h"
#include "io/ycbcr.h"
#include "xr/session.h"

namespace vdfx::app {

effects::FlareSet flare_set_of(const io::Sidecar& sidecar) {
  try {
    return effects::FlareSet(sidecar.flares, sidecar.interpolation, sidecar.video.fps);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string("sidecar flares cannot be interpolated: ") + e.what());
  }
}

std::vector<effects::FlareLayout> flare_layouts(effects::FlareSet& set, const xr::Pose& head,
                                                std::int64_t frame, const io::Picture* picture) {
  if (set.empty()) return {};
  if (set.uses_auto_light() && picture && !set.observed(frame))
    set.observe(frame, io::to_rgb(*picture, io::PixelFormat::RgbF32));
  return set.layouts({xr::position_of(head), xr::rotation_of(head)}, frame);
}

}  // namespace vdfx::app
