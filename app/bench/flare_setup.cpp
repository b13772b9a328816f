/// @file
/// @brief The benchmarks' flare scene.
#include "app/bench/flare_setup.h"

#include <stdexcept>

#include "app/bench/inputs.h"

namespace vdfx::app::bench {

effects::FlareLayout flare_layout(effects::FlareStyle style, int rings) {
  effects::FlareSettings s = effects::default_flare_settings(style);
  s.rings = rings;
  const xr::Pose h = head_at(kFlareLook);
  const auto l = effects::layout_flare(style, s, {xr::position_of(h), xr::rotation_of(h)},
                                       effects::to_unit(kFlareLight), 1.0);
  if (!l) throw std::logic_error("the bench flare adds nothing");
  return *l;
}

}  // namespace vdfx::app::bench
