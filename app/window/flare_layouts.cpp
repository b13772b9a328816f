/// @file
/// @brief flare_layouts: an auto light observed once per frame, then the set's layouts.
#include "app/window/flare_layouts.h"

#include "effects/flare_set_cv.h"
#include "io/ycbcr.h"
#include "xr/headset/session.h"

namespace vdfx::app {

std::vector<effects::FlareLayout> flare_layouts(effects::FlareSet& set, const xr::Pose& head,
                                                std::int64_t frame, const io::Picture* picture) {
  if (set.empty()) return {};
  if (set.uses_auto_light() && picture && !set.observed(frame))
    effects::observe_frame(set, frame, io::to_rgb(*picture, io::PixelFormat::RgbF32));
  return set.layouts({xr::position_of(head), xr::rotation_of(head)}, frame);
}

}  // namespace vdfx::app
